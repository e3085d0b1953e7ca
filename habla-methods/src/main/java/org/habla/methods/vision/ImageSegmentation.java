package org.habla.methods.vision;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The image segmentation method, type {@code image-segmentation}: finds the regions of the configured
 * colour classes in camera frames (input {@code image}: JPEG, PNG, {@code bgr8} or {@code gray8}) with
 * OpenCV and emits them on {@code blobs} as {@code {"width","height","blobs":[{"label","cx","cy","area",
 * "x","y","w","h"}…]}}, largest first, pixels from the top-left corner. Output {@code largest} follows
 * the first colour class alone: its largest blob with {@code "seen": true}, or {@code "seen": false}.
 *
 * <p>The work runs in the background, one frame at a time, so a camera never holds up the engine:
 * while a frame is being segmented only the newest frame that arrives waits, older ones are dropped
 * (and counted in {@link #droppedFrames()}). Loading the OpenCV natives also runs in the background;
 * the method reports itself not ready until it is done. A frame that cannot be decoded is skipped
 * with a warning; the method carries on with the next.
 */
public final class ImageSegmentation extends ProcessingMethod {

    private static final InputPort<ImageFrame> IMAGE = InputPort.of("image", ImageFrame.class, Delivery.latest());
    private static final OutputPort<RecordValue> BLOBS = OutputPort.of("blobs", RecordValue.class, Shape.record(
            "regions of each colour class in pixels, largest first", BlobList.LAYOUT));
    private static final OutputPort<RecordValue> LARGEST = OutputPort.of("largest", RecordValue.class, Shape.record(
            "the largest region of the first colour class", "seen", "label", "cx", "cy", "area", "x", "y", "w", "h",
            "width", "height"));
    static final Ports PORTS = Ports.of(IMAGE, BLOBS, LARGEST);

    private final ImageSegmentationParams params;
    private final Output<RecordValue> blobs = output(BLOBS);
    private final Output<RecordValue> largest = output(LARGEST);

    private ColorSegmenter segmenter;
    private boolean busy;
    private ImageFrame waiting;
    private long waitingSourceMicros;
    private long dropped;
    private long unreadable;

    ImageSegmentation(ImageSegmentationParams params) {
        this.params = params;
        input(IMAGE, this::onImage);
    }

    @Override
    protected void onStart() {
        readiness(false, "loading OpenCV");
        busy = true;
        background("load OpenCV", () -> {
            OpenCvLibrary.load();
            return new ColorSegmenter(params);
        }, this::onLoaded);
    }

    private void onLoaded(ColorSegmenter loaded) {
        segmenter = loaded;
        readiness(true, "OpenCV " + org.opencv.core.Core.VERSION);
        next();
    }

    private void onImage(ImageFrame frame, Sample sample) {
        if (waiting != null) {
            dropped++;
        }
        waiting = frame;
        waitingSourceMicros = sample.sourceMicros();
        if (!busy) {
            next();
        }
    }

    /** Starts on the waiting frame, if any; otherwise goes idle. */
    private void next() {
        if (waiting == null) {
            busy = false;
            return;
        }
        ImageFrame frame = waiting;
        long sourceMicros = waitingSourceMicros;
        waiting = null;
        busy = true;
        background("segment " + frame, () -> segmentQuietly(frame), s -> onSegmented(s, sourceMicros));
    }

    private Segmentation segmentQuietly(ImageFrame frame) {
        try {
            return segmenter.segment(frame);
        } catch (RuntimeException e) {
            return Segmentation.unreadable(frame + ": " + e.getMessage());
        }
    }

    private void onSegmented(Segmentation s, long sourceMicros) {
        if (s.readable()) {
            emit(blobs, s.toRecord(), sourceMicros);
            emit(largest, s.largestRecord(params.firstLabel()), sourceMicros);
        } else {
            unreadable++;
            if (Long.bitCount(unreadable) == 1) {   // the 1st, 2nd, 4th, 8th…: a broken camera does not flood the log
                log().warn("{}: skipped an unreadable frame ({} so far): {}", id(), unreadable, s.error());
            }
        }
        next();
    }

    /** Frames dropped because a newer one arrived while a frame was being segmented. */
    public long droppedFrames() {
        return dropped;
    }

    /** Frames that could not be decoded. */
    public long unreadableFrames() {
        return unreadable;
    }

    /** Makes {@code image-segmentation} methods. */
    public static final class Provider extends SimpleMethodProvider<ImageSegmentationParams> {
        public Provider() {
            super("image-segmentation", "Finds the regions of configured colours in camera frames with OpenCV",
                    ImageSegmentationParams.class, PORTS, (layer, p) -> new ImageSegmentation(p), Layer.PROCESSING);
        }
    }
}
