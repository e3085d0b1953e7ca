package org.habla.net;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.UncheckedIOException;

/**
 * A frame already turned into what goes on the wire: its header line's bytes (compact JSON and the newline,
 * {@code "bytes"} set when there is a body) and its body. A sample sent to many clients is encoded once and
 * every client's writer sends the same bytes; nobody may change them.
 *
 * <pre>
 *   frame --encode once--&gt; EncodedFrame(line, body) --&gt; outbox 1 --&gt; socket 1
 *                                                 \--&gt; outbox 2 --&gt; socket 2   (same arrays, no copy)
 * </pre>
 *
 * @param frame the frame it was encoded from, for what it says ({@link Frame#type()})
 * @param line  the header as one line, newline included
 */
record EncodedFrame(Frame frame, byte[] line) {

    private static final byte NEWLINE = '\n';

    /** What a sample encoded straight to its line ({@link #sample}) says of its frame: its type, and no body. */
    private static final Frame SAMPLE = Frame.of(com.fasterxml.jackson.databind.node.JsonNodeFactory.instance
            .objectNode().put("type", "sample"));

    /**
     * Encodes the sample line of one output's sample, straight from its payload where it has no body
     * ({@link SampleLine}), else through its frame.
     */
    static EncodedFrame sample(String output, org.habla.sample.Sample sample) {
        byte[] line = SampleLine.of(output, sample);
        return line != null ? new EncodedFrame(SAMPLE, line) : of(SampleCodec.sampleFrame(output, sample));
    }

    /** Encodes {@code frame}; a frame with a body gets {@code "bytes"} set to the body's length. */
    static EncodedFrame of(Frame frame) {
        ObjectNode header = frame.header();
        boolean declares = frame.body().length > 0 || frame.hasBody();
        if (declares && header.path("bytes").asLong(-1) != frame.body().length) {
            header = header.deepCopy().put("bytes", frame.body().length);
        }
        byte[] json;
        try {
            json = FrameWriter.toLine(header);
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException("cannot encode a frame of type '" + frame.type() + "'", e);
        }
        byte[] line = java.util.Arrays.copyOf(json, json.length + 1);
        line[json.length] = NEWLINE;
        return new EncodedFrame(frame, line);
    }

    /** The body that follows the line, possibly empty. */
    byte[] body() {
        return frame.body();
    }

    /** The frame's {@code type}. */
    String type() {
        return frame.type();
    }
}
