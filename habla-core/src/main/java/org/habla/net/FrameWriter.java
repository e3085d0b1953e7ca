package org.habla.net;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;

/**
 * Writes frames (see {@link FrameReader} for the layout): the header as one compact JSON line, then the
 * body if there is one, with {@code "bytes"} set to the body's length. Buffered: call {@link #flush} after a
 * frame or after a batch. Not thread-safe: one writer thread per stream.
 */
public final class FrameWriter {

    private final OutputStream raw;
    private final OutputStream out;

    public FrameWriter(OutputStream out) {
        // Without a size, a stream made on a virtual thread (every served connection's writer) starts with a
        // small buffer that grows as batches need it: an idle connection holds 512 bytes, not 16 KB.
        this.raw = out;
        this.out = new BufferedOutputStream(out);
    }

    /** Writes a frame without flushing; a frame with a body gets {@code "bytes"} set to its length. */
    public void write(Frame frame) throws IOException {
        EncodedFrame encoded;
        try {
            encoded = EncodedFrame.of(frame);
        } catch (java.io.UncheckedIOException e) {
            throw e.getCause();
        }
        write(encoded);
    }

    /** Writes a frame encoded before, as it is, without flushing. */
    void write(EncodedFrame frame) throws IOException {
        out.write(frame.line());
        if (frame.body().length > 0) {
            out.write(frame.body());
        }
    }

    /**
     * Writes a batch of encoded frames and flushes. A batch of one frame without a body (a sample to a client that
     * keeps up) goes to the stream as it is, in one write and without a copy into the buffer.
     */
    void send(java.util.List<EncodedFrame> batch) throws IOException {
        if (batch.size() == 1 && batch.getFirst().body().length == 0) {
            out.flush(); // nothing is buffered between batches; kept so the order can never change
            raw.write(batch.getFirst().line());
            return;
        }
        for (EncodedFrame f : batch) {
            write(f);
        }
        out.flush();
    }

    /** Writes a header-only frame without flushing. */
    public void write(ObjectNode header) throws IOException {
        write(Frame.of(header));
    }

    /** Writes a frame and flushes. */
    public void send(Frame frame) throws IOException {
        write(frame);
        flush();
    }

    /** Writes a header-only frame and flushes. */
    public void send(ObjectNode header) throws IOException {
        send(Frame.of(header));
    }

    public void flush() throws IOException {
        out.flush();
    }

    /** The header as the bytes of one line (Jackson writes compact JSON and escapes control characters). */
    static byte[] toLine(ObjectNode header) throws JsonProcessingException {
        return FrameReader.JSON.writeValueAsBytes(header);
    }
}
