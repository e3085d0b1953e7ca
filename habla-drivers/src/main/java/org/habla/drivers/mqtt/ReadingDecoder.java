package org.habla.drivers.mqtt;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * Turns one message into the reading of one {@link ReadingMap}: the whole payload, or one JSON field of it, as
 * the channel's kind.
 *
 * <pre>
 *   payload                                   field                kind     reading
 *   {"occupancy":true,"illuminance":310}      occupancy            number   1
 *   {"AM2301":{"Temperature":21.5}}           AM2301.Temperature   number   21.5
 *   21.5                                      (none)               number   21.5
 *   {"state":"ON","brightness":128}           (none)               record   {"state":"ON","brightness":128}
 *   ON                                        (none)               number   1
 * </pre>
 *
 * A message without the field is no reading for this channel (devices publish their whole state, and not every
 * state holds every field): empty, not an error. A payload that cannot be read as the kind is an error.
 */
final class ReadingDecoder {

    /** Text values every number channel knows. */
    private static final Map<String, Double> KNOWN = Map.of("true", 1.0, "false", 0.0, "on", 1.0, "off", 0.0,
            "open", 1.0, "closed", 0.0, "online", 1.0, "offline", 0.0);
    private static final ObjectMapper JSON = new ObjectMapper();

    private final ReadingMap map;
    private final String[] path;

    ReadingDecoder(ReadingMap map) {
        this.map = map;
        this.path = map.field().isEmpty() ? new String[0] : map.field().split("\\.");
    }

    ReadingMap map() {
        return map;
    }

    /** The reading, empty if the message has no such field; {@link IllegalArgumentException} if it cannot be read. */
    Optional<Payload> decode(byte[] payload) {
        String text = new String(payload, StandardCharsets.UTF_8);
        JsonNode node;
        if (path.length == 0) {
            node = map.payloadKind() == PayloadKind.TEXT ? null : parseOrNull(text);
            if (node == null) {
                return Optional.of(fromText(text.strip()));
            }
        } else {
            node = parseOrNull(text);
            if (node == null || !node.isObject()) {
                throw new IllegalArgumentException("the payload is not a JSON object, so it has no field '"
                        + map.field() + "'");
            }
            for (String step : path) {
                node = node.get(step);
                if (node == null) {
                    return Optional.empty();
                }
            }
        }
        return Optional.of(fromJson(node));
    }

    private Payload fromJson(JsonNode node) {
        return switch (map.payloadKind()) {
            case NUMBER -> {
                if (node.isNumber()) {
                    yield number(node.doubleValue());
                }
                if (node.isBoolean()) {
                    yield new NumberValue(node.booleanValue() ? 1 : 0);
                }
                if (node.isTextual()) {
                    yield fromText(node.textValue());
                }
                throw new IllegalArgumentException("'" + abbreviate(node.toString()) + "' is not a number");
            }
            case TEXT -> new TextValue(node.isTextual() ? node.textValue() : node.toString());
            case RECORD -> {
                if (!node.isObject()) {
                    throw new IllegalArgumentException("'" + abbreviate(node.toString()) + "' is not a JSON object");
                }
                yield RecordValue.of((ObjectNode) node);
            }
            case VECTOR -> {
                if (!node.isArray()) {
                    throw new IllegalArgumentException("'" + abbreviate(node.toString()) + "' is not a JSON array");
                }
                double[] v = new double[node.size()];
                for (int i = 0; i < v.length; i++) {
                    if (!node.get(i).isNumber()) {
                        throw new IllegalArgumentException("element " + i + " of the array is not a number");
                    }
                    v[i] = node.get(i).doubleValue();
                }
                yield VectorValue.wrap(v);
            }
            default -> throw new IllegalStateException("kind " + map.payloadKind());
        };
    }

    private Payload fromText(String text) {
        switch (map.payloadKind()) {
            case TEXT:
                return new TextValue(text);
            case NUMBER:
                Double mapped = map.values().get(text);
                if (mapped == null) {
                    mapped = KNOWN.get(text.toLowerCase(Locale.ROOT));
                }
                if (mapped != null) {
                    return new NumberValue(mapped);
                }
                try {
                    return number(Double.parseDouble(text));
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + abbreviate(text) + "' is not a number");
                }
            default:
                throw new IllegalArgumentException("'" + abbreviate(text) + "' is not JSON");
        }
    }

    private static NumberValue number(double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(v + " is not a finite number");
        }
        return new NumberValue(v);
    }

    private static JsonNode parseOrNull(String text) {
        String t = text.strip();
        if (t.isEmpty() || "{[\"".indexOf(t.charAt(0)) < 0 && !Character.isDigit(t.charAt(0)) && t.charAt(0) != '-'
                && !t.equals("true") && !t.equals("false")) {
            return null;
        }
        try {
            return JSON.readTree(t);
        } catch (JsonProcessingException e) {
            return null;
        }
    }

    static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 57) + "...";
    }
}
