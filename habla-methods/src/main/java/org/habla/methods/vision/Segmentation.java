package org.habla.methods.vision;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Optional;
import org.habla.sample.RecordValue;

/**
 * What {@link ColorSegmenter} found in one frame: the frame size and the blobs of every class, largest
 * first; or why the frame could not be read.
 *
 * @param width  frame width in pixels (0 if unreadable)
 * @param height frame height in pixels (0 if unreadable)
 * @param blobs  blobs of every class, largest first
 * @param error  why the frame was unreadable, or empty
 */
public record Segmentation(int width, int height, List<Blob> blobs, String error) {

    public Segmentation {
        blobs = List.copyOf(blobs);
    }

    static Segmentation unreadable(String why) {
        return new Segmentation(0, 0, List.of(), why);
    }

    public boolean readable() {
        return error.isEmpty();
    }

    /** The largest blob of {@code label}, if any. */
    public Optional<Blob> largest(String label) {
        return blobs.stream().filter(b -> b.label().equals(label)).findFirst();
    }

    /** The {@code blobs} record: {@code {"width","height","blobs":[...]}}, carrying a {@link BlobList}. */
    public RecordValue toRecord() {
        return RecordValue.of(new BlobList(width, height, blobs.stream().map(BlobList.Entry::of).toList()));
    }

    /**
     * The {@code largest} record of one class: the blob's fields and the frame size, with
     * {@code "seen": true}; when the class is absent {@code "seen": false} and zeros.
     */
    public RecordValue largestRecord(String label) {
        Optional<Blob> b = largest(label);
        ObjectNode o = b.map(Blob::toJson).orElseGet(() -> new Blob(label, 0, 0, 0, 0, 0, 0, 0).toJson());
        o.put("seen", b.isPresent());
        o.put("width", width);
        o.put("height", height);
        return RecordValue.of(o);
    }
}
