package org.habla.recording;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.UncheckedIOException;

/** The JSON Schemas of an MCAP recording's messages: one per record type and payload kind. */
final class McapSchemas {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final ObjectMapper JSON = new ObjectMapper();

    private McapSchemas() {
    }

    static byte[] of(String type, String kind, boolean image) {
        ObjectNode s = NODES.objectNode().put("$schema", "https://json-schema.org/draft/2020-12/schema")
                .put("title", image ? "foxglove.CompressedImage" : "habla." + type + (kind.isEmpty() ? "" : "." + kind))
                .put("type", "object");
        ObjectNode p = s.putObject("properties");
        p.putObject("type").put("type", "string").put("const", type);
        p.putObject("t").put("type", "integer").put("description", "when HABLA saw it: engine clock, µs since the epoch");
        switch (type) {
            case "reading", "command" -> {
                p.putObject("iface").put("type", "string");
                p.putObject("channel").put("type", "string");
            }
            case "control" -> {
                p.putObject("socket").put("type", "string");
                p.putObject("input").put("type", "string");
            }
            case "output" -> {
                p.putObject("method").put("type", "string");
                p.putObject("output").put("type", "string");
            }
            case "link" -> p.putObject("up").put("type", "boolean");
            case "tick" -> {
                p.putObject("task").put("type", "string");
                p.putObject("handled").put("type", "integer");
            }
            case "skip" -> {
                p.putObject("method").put("type", "string");
                p.putObject("input").put("type", "string");
                p.putObject("arrival").put("type", "integer")
                        .put("description", "the skipped sample's place among those offered to the input, from 1");
            }
            default -> { }
        }
        if (!kind.isEmpty()) {
            p.putObject("producer").put("type", "string");
            p.putObject("seq").put("type", "integer");
            p.putObject("src").put("type", "integer").put("description", "source time of the raw reading, µs since the epoch");
            p.putObject("stale").put("type", "boolean");
            p.putObject("kind").put("type", "string").put("const", kind);
            switch (kind) {
                case "number" -> p.putObject("value").putArray("type").add("number").add("null");
                case "vector" -> p.putObject("value").put("type", "array").putObject("items").putArray("type")
                        .add("number").add("null");
                case "text" -> p.putObject("value").put("type", "string");
                case "record" -> p.putObject("value").put("type", "object");
                case "audio" -> {
                    p.putObject("rateHz").put("type", "integer");
                    p.putObject("channels").put("type", "integer");
                    p.putObject("bits").put("type", "integer");
                    p.putObject("bytes").put("type", "integer");
                    p.putObject("data").put("type", "string").put("contentEncoding", "base64");
                }
                case "image" -> {
                    p.putObject("width").put("type", "integer");
                    p.putObject("height").put("type", "integer");
                    p.putObject("encoding").put("type", "string");
                    p.putObject("bytes").put("type", "integer");
                    p.putObject("data").put("type", "string").put("contentEncoding", "base64");
                    if (image) {
                        ObjectNode ts = p.putObject("timestamp").put("type", "object");
                        ts.putObject("properties").<ObjectNode>set("sec", NODES.objectNode().put("type", "integer"))
                                .set("nsec", NODES.objectNode().put("type", "integer"));
                        p.putObject("frame_id").put("type", "string");
                        p.putObject("format").put("type", "string");
                    }
                }
                default -> { }
            }
        }
        try {
            return JSON.writeValueAsBytes(s);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }
}
