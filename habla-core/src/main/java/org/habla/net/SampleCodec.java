package org.habla.net;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Iterator;
import java.util.Map;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordJson;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * Turns payloads and samples into frame fields and back; the one place that knows how each payload kind
 * looks on a HABLA socket.
 *
 * <pre>
 *   kind     header fields                                              body
 *   number   "kind":"number", "value": 0.5          (NaN, ±Infinity -&gt; null)  -
 *   vector   "kind":"vector", "value": [1.0, 2.5]   (non-finite -&gt; null)      -
 *   text     "kind":"text",   "value": "forward"                             -
 *   record   "kind":"record", "value": {"distanceM": 1.2, ...}               -
 *   audio    "kind":"audio",  "rateHz":16000, "channels":1, "bits":16, "bytes":N   N bytes of PCM (LE, interleaved)
 *   image    "kind":"image",  "width":W, "height":H, "encoding":"jpeg", "bytes":N  N bytes of image data
 * </pre>
 *
 * A sample line adds {@code "type":"sample","output":NAME,"seq":N,"t":MICROS,"stale":BOOL}. JSON has no
 * NaN or infinity, so non-finite numbers travel as {@code null} and a {@code null} number reads back as NaN.
 */
public final class SampleCodec {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private SampleCodec() {
    }

    /** The sample line of one output's sample. */
    public static Frame sampleFrame(String output, Sample sample) {
        ObjectNode header = NODES.objectNode()
                .put("type", "sample")
                .put("output", output)
                .put("seq", sample.sequence())
                .put("t", sample.sourceMicros())
                .put("stale", sample.stale());
        return withValue(header, sample.payload());
    }

    /** Adds {@code kind} and the value fields of {@code payload} to {@code header}; the body if binary. */
    public static Frame withValue(ObjectNode header, Payload payload) {
        header.put("kind", payload.kind().wireName());
        switch (payload) {
            case NumberValue n -> header.set("value", number(n.value()));
            case VectorValue v -> {
                ArrayNode array = header.putArray("value");
                for (int i = 0; i < v.size(); i++) {
                    array.add(number(v.get(i)));
                }
            }
            case TextValue t -> header.put("value", t.text());
            case RecordValue r -> header.set("value",
                    RecordJson.allFinite(r.jsonView()) ? r.jsonView() : finite(r.json()));
            case AudioChunk a -> {
                header.put("rateHz", a.format().sampleRateHz())
                        .put("channels", a.format().channels())
                        .put("bits", a.format().bitsPerSample())
                        .put("bytes", a.byteCount());
                return new Frame(header, a.pcm());
            }
            case ImageFrame f -> {
                header.put("width", f.width())
                        .put("height", f.height())
                        .put("encoding", f.encoding())
                        .put("bytes", f.byteCount());
                return new Frame(header, f.data());
            }
        }
        return Frame.of(header);
    }

    /**
     * Reads the value a frame carries, for a port of kind {@code expected} ({@link PayloadKind#ANY} takes the
     * frame's own {@code kind}, or guesses it from the JSON type of {@code value}).
     *
     * @throws FrameException {@code bad_value}, saying what was expected
     */
    public static Payload value(Frame frame, PayloadKind expected) throws FrameException {
        ObjectNode h = frame.header();
        PayloadKind kind = kindOf(h, expected);
        JsonNode value = h.get("value");
        if (kind != PayloadKind.AUDIO && kind != PayloadKind.IMAGE && value == null) {
            throw FrameException.badValue("no \"value\": expected " + describe(kind));
        }
        try {
            return switch (kind) {
                case NUMBER -> new NumberValue(number(value, "a number (or null for NaN)"));
                case VECTOR -> vector(value);
                case TEXT -> {
                    if (!value.isTextual()) {
                        throw FrameException.badValue("expected " + describe(kind) + ", got " + type(value));
                    }
                    yield new TextValue(value.textValue());
                }
                case RECORD -> {
                    if (!(value instanceof ObjectNode object)) {
                        throw FrameException.badValue("expected " + describe(kind) + ", got " + type(value));
                    }
                    yield RecordValue.of(object);
                }
                case AUDIO -> AudioChunk.wrap(new AudioFormat(whole(h, "rateHz"), whole(h, "channels"),
                        whole(h, "bits")), body(frame, kind));
                case IMAGE -> {
                    JsonNode encoding = h.get("encoding");
                    if (encoding == null || !encoding.isTextual()) {
                        throw FrameException.badValue("an image needs \"encoding\" (e.g. \"jpeg\")");
                    }
                    yield ImageFrame.wrap(whole(h, "width"), whole(h, "height"), encoding.textValue(),
                            body(frame, kind));
                }
                case ANY -> throw new IllegalStateException("kind was resolved above");
            };
        } catch (IllegalArgumentException e) {
            throw FrameException.badValue(e.getMessage());
        }
    }

    /** Reads a sample line back into a sample made by {@code producer}. */
    public static Sample sample(Frame frame, String producer) throws FrameException {
        ObjectNode h = frame.header();
        Payload payload = value(frame, PayloadKind.ANY);
        return new Sample(payload, producer, h.path("seq").asLong(0), h.path("t").asLong(0),
                h.path("stale").asBoolean(false));
    }

    /** How a value of {@code kind} is written, for error messages and docs. */
    public static String describe(PayloadKind kind) {
        return switch (kind) {
            case NUMBER -> "a number";
            case VECTOR -> "an array of numbers";
            case TEXT -> "a string";
            case RECORD -> "a JSON object";
            case AUDIO -> "audio (\"rateHz\", \"channels\", \"bits\" and \"bytes\": N, then N bytes of PCM)";
            case IMAGE -> "an image (\"width\", \"height\", \"encoding\" and \"bytes\": N, then N bytes)";
            case ANY -> "a value";
        };
    }

    private static PayloadKind kindOf(ObjectNode h, PayloadKind expected) throws FrameException {
        JsonNode named = h.get("kind");
        if (named != null) {
            PayloadKind kind;
            try {
                kind = PayloadKind.fromWire(named.asText());
            } catch (IllegalArgumentException e) {
                throw FrameException.badValue(e.getMessage());
            }
            if (kind == PayloadKind.ANY || !expected.accepts(kind)) {
                throw FrameException.badValue("expected " + describe(expected) + ", got \"kind\": " + named);
            }
            return kind;
        }
        if (expected != PayloadKind.ANY) {
            return expected;
        }
        JsonNode value = h.get("value");
        if (value == null) {
            if (h.has("rateHz")) {
                return PayloadKind.AUDIO;
            }
            if (h.has("width")) {
                return PayloadKind.IMAGE;
            }
            throw FrameException.badValue("no \"value\" and no \"kind\"");
        }
        if (value.isNumber() || value.isNull()) {
            return PayloadKind.NUMBER;
        }
        if (value.isArray()) {
            return PayloadKind.VECTOR;
        }
        if (value.isTextual()) {
            return PayloadKind.TEXT;
        }
        if (value.isObject()) {
            return PayloadKind.RECORD;
        }
        throw FrameException.badValue("cannot tell the kind of a " + type(value) + " value");
    }

    private static VectorValue vector(JsonNode value) throws FrameException {
        if (!value.isArray()) {
            throw FrameException.badValue("expected an array of numbers, got " + type(value));
        }
        double[] out = new double[value.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = number(value.get(i), "an array of numbers (element " + i + ")");
        }
        return VectorValue.wrap(out);
    }

    private static double number(JsonNode node, String expected) throws FrameException {
        if (node.isNull()) {
            return Double.NaN;
        }
        if (!node.isNumber()) {
            throw FrameException.badValue("expected " + expected + ", got " + type(node));
        }
        return node.doubleValue();
    }

    private static int whole(ObjectNode h, String field) throws FrameException {
        JsonNode n = h.get(field);
        if (n == null || !n.isIntegralNumber() || !n.canConvertToInt()) {
            throw FrameException.badValue("\"" + field + "\" must be a whole number, was " + n);
        }
        return n.intValue();
    }

    private static byte[] body(Frame frame, PayloadKind kind) throws FrameException {
        if (!frame.hasBody()) {
            throw FrameException.badValue("expected " + describe(kind) + "; \"bytes\" is missing");
        }
        return frame.body();
    }

    private static JsonNode number(double v) {
        return Double.isFinite(v) ? NODES.numberNode(v) : NODES.nullNode();
    }

    /** Replaces non-finite numbers, which JSON cannot carry, by null (in place; {@code node} is a copy). */
    static JsonNode finite(JsonNode node) {
        if (node.isFloatingPointNumber() && !Double.isFinite(node.doubleValue())) {
            return NODES.nullNode();
        }
        if (node instanceof ObjectNode object) {
            for (Iterator<Map.Entry<String, JsonNode>> it = object.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                e.setValue(finite(e.getValue()));
            }
        } else if (node instanceof ArrayNode array) {
            for (int i = 0; i < array.size(); i++) {
                array.set(i, finite(array.get(i)));
            }
        }
        return node;
    }

    private static String type(JsonNode node) {
        return node.getNodeType().name().toLowerCase(java.util.Locale.ROOT)
                + (node.isValueNode() ? " " + abbreviate(node.toString()) : "");
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
