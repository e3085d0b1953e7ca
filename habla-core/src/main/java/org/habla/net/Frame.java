package org.habla.net;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;

/**
 * One frame of the HABLA wire protocol: a JSON object header and the raw bytes that followed it
 * (empty unless the header declared {@code "bytes": N}). See {@link FrameReader} for the layout.
 *
 * <p>The frame owns its header and body; whoever holds a frame may read them but must not change them
 * once the frame is handed on.
 */
public record Frame(ObjectNode header, byte[] body) {

    private static final byte[] NONE = new byte[0];

    public Frame {
        Objects.requireNonNull(header, "header");
        body = body == null ? NONE : body;
    }

    /** A frame of a header alone. */
    public static Frame of(ObjectNode header) {
        return new Frame(header, NONE);
    }

    /** The header's {@code type} field, or an empty string. */
    public String type() {
        return header.path("type").asText("");
    }

    /** Whether the header declared a binary block (possibly empty). */
    public boolean hasBody() {
        return header.has("bytes");
    }
}
