package org.habla.monitor;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.Base64;
import org.habla.graph.OutputInfo;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordField;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * One method output as a channel of the Foxglove WebSocket protocol: topic {@code /METHOD/OUTPUT}, JSON
 * encoding, and a JSON Schema of its messages. A sample is sent as a control socket shows it —
 * {@code {"seq", "sourceMicros", "stale", "value"}} — so a number plots as {@code .value}, a vector element
 * as {@code .value[0]} and a record field as {@code .value.distanceM}. Images go as
 * {@code foxglove.CompressedImage} (raw frames encoded to PNG), audio as {@code habla.AudioChunk} with its
 * level in dBFS beside the base64 PCM.
 */
record FoxgloveChannel(int id, OutputInfo output, String topic, String schemaName, String schema) {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    static FoxgloveChannel of(int id, OutputInfo output) {
        String topic = "/" + output.methodId() + "/" + output.output();
        ObjectNode schema = NODES.objectNode().put("$schema", "https://json-schema.org/draft/2020-12/schema");
        String name;
        switch (output.shape().kind()) {
            case IMAGE -> {
                name = "foxglove.CompressedImage";
                schema.put("title", name).put("description", "A compressed image").put("type", "object");
                ObjectNode p = schema.putObject("properties");
                ObjectNode ts = p.putObject("timestamp").put("type", "object").put("title", "time");
                ts.putObject("properties").<ObjectNode>set("sec", NODES.objectNode().put("type", "integer").put("minimum", 0))
                        .set("nsec", NODES.objectNode().put("type", "integer").put("minimum", 0).put("maximum", 999_999_999));
                p.putObject("frame_id").put("type", "string");
                p.putObject("data").put("type", "string").put("contentEncoding", "base64");
                p.putObject("format").put("type", "string");
            }
            case AUDIO -> {
                name = "habla.AudioChunk";
                envelope(schema, name, output);
                ObjectNode p = (ObjectNode) schema.get("properties");
                p.putObject("rateHz").put("type", "integer");
                p.putObject("channels").put("type", "integer");
                p.putObject("bits").put("type", "integer");
                p.putObject("levelDb").put("type", "number").put("description", "RMS level of the first channel, dB below full scale");
                p.putObject("data").put("type", "string").put("contentEncoding", "base64")
                        .put("description", "little-endian signed PCM, channels interleaved");
            }
            default -> {
                name = "habla." + output.shape().kind().wireName() + "." + output.methodId() + "." + output.output();
                envelope(schema, name, output);
                ((ObjectNode) schema.get("properties")).set("value", valueSchema(output));
            }
        }
        try {
            return new FoxgloveChannel(id, output, topic, name, JSON.writeValueAsString(schema));
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    private static void envelope(ObjectNode schema, String name, OutputInfo output) {
        schema.put("title", name).put("type", "object");
        if (!output.shape().doc().isEmpty()) {
            schema.put("description", output.shape().doc());
        }
        ObjectNode p = schema.putObject("properties");
        p.putObject("seq").put("type", "integer").put("description", "the output's running count, from 1");
        p.putObject("sourceMicros").put("type", "integer")
                .put("description", "when the raw reading it derives from was taken, µs since the epoch");
        p.putObject("stale").put("type", "boolean").put("description", "a link it depends on is down");
    }

    private static ObjectNode valueSchema(OutputInfo output) {
        String unit = output.shape().unit();
        ObjectNode v = NODES.objectNode();
        switch (output.shape().kind()) {
            case NUMBER -> v.putArray("type").add("number").add("null");
            case TEXT -> v.put("type", "string");
            case VECTOR -> {
                v.put("type", "array").putObject("items").putArray("type").add("number").add("null");
                if (!output.shape().fields().isEmpty()) {
                    ArrayNode names = v.putArray("x-elements");
                    output.shape().fields().forEach(names::add);
                }
            }
            case RECORD -> {
                v.put("type", "object");
                ObjectNode props = v.putObject("properties");
                output.shape().fields().forEach(f -> props.putObject(f));
                for (RecordField f : output.shape().recordFields()) {
                    props.putObject(f.name()).put("description", f.toString());
                }
            }
            default -> { }
        }
        if (!unit.isEmpty()) {
            v.put("description", "unit: " + unit);
        }
        return v;
    }

    /** The advertisement of this channel. */
    ObjectNode advertisement() {
        return NODES.objectNode().put("id", id).put("topic", topic).put("encoding", "json")
                .put("schemaName", schemaName).put("schema", schema).put("schemaEncoding", "jsonschema");
    }

    /** A sample as this channel's JSON message. */
    byte[] encode(Sample sample) throws IOException {
        ObjectNode m = NODES.objectNode();
        switch (sample.payload()) {
            case ImageFrame f -> {
                ViewableImage img = ViewableImage.of(f);
                long micros = sample.sourceMicros();
                m.putObject("timestamp").put("sec", micros / 1_000_000).put("nsec", (micros % 1_000_000) * 1_000);
                m.put("frame_id", output.methodId());
                m.put("data", Base64.getEncoder().encodeToString(img.bytes()));
                m.put("format", img.format());
                return JSON.writeValueAsBytes(m);
            }
            case AudioChunk a -> {
                head(m, sample);
                m.put("rateHz", a.format().sampleRateHz()).put("channels", a.format().channels())
                        .put("bits", a.format().bitsPerSample()).put("levelDb", ViewedMethod.levelDb(a))
                        .put("data", Base64.getEncoder().encodeToString(a.pcm()));
                return JSON.writeValueAsBytes(m);
            }
            default -> {
                head(m, sample);
                m.set("value", value(sample.payload()));
                return JSON.writeValueAsBytes(m);
            }
        }
    }

    private static void head(ObjectNode m, Sample s) {
        m.put("seq", s.sequence()).put("sourceMicros", s.sourceMicros()).put("stale", s.stale());
    }

    private static com.fasterxml.jackson.databind.JsonNode value(Payload p) {
        return switch (p) {
            case NumberValue n -> Double.isFinite(n.value()) ? NODES.numberNode(n.value()) : NODES.nullNode();
            case VectorValue v -> {
                ArrayNode a = NODES.arrayNode();
                for (double d : v.toArray()) {
                    if (Double.isFinite(d)) {
                        a.add(d);
                    } else {
                        a.addNull();
                    }
                }
                yield a;
            }
            case TextValue t -> NODES.textNode(t.text());
            case RecordValue r -> r.json();
            default -> NODES.nullNode();
        };
    }
}
