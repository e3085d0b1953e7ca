package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * The payload of a command message, written with placeholders:
 *
 * <pre>
 *   template                                   command                         message
 *   {{value}}                                  record {"state":"ON"}           {"state":"ON"}
 *   {"brightness": {{value}}}                  number 128                      {"brightness": 128}
 *   {"state": "{{value}}"}                     text ON                         {"state": "ON"}
 *   {{state}}                                  record {"state":"OFF"}          OFF
 * </pre>
 *
 * {@code {{value}}} is the whole command: a number in plain decimal (whole numbers without a fraction), a text as it
 * is, a record or a vector as JSON. {@code {{name}}} is a field of a record command (a text field as its text,
 * anything else as JSON); a record without that field is refused, so no half-made message is ever sent.
 */
record PayloadTemplate(String text) {

    private static final Pattern PLACEHOLDER = Pattern.compile("\\{\\{\\s*([A-Za-z_][A-Za-z0-9_]*)\\s*}}");

    PayloadTemplate {
        if (text == null) {
            throw new IllegalArgumentException("template cannot be null");
        }
        if (!PLACEHOLDER.matcher(text).find() && text.contains("{{")) {
            throw new IllegalArgumentException("template '" + text + "' has a '{{' that is no {{name}} placeholder");
        }
    }

    /** The names of the placeholders, in order. */
    List<String> names() {
        List<String> names = new ArrayList<>();
        Matcher m = PLACEHOLDER.matcher(text);
        while (m.find()) {
            names.add(m.group(1));
        }
        return names;
    }

    /** The message for a command; {@link IllegalArgumentException} if the command lacks a field the template names. */
    String render(Payload command) {
        Matcher m = PLACEHOLDER.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String name = m.group(1);
            m.appendReplacement(out, Matcher.quoteReplacement(name.equals("value") ? whole(command) : field(command, name)));
        }
        m.appendTail(out);
        return out.toString();
    }

    private static String whole(Payload command) {
        return switch (command) {
            case NumberValue n -> number(n.value());
            case TextValue t -> t.text();
            case RecordValue r -> r.jsonView().toString();
            case VectorValue v -> vector(v.toArray());
            default -> throw new IllegalArgumentException("a " + command.kind().wireName() + " cannot go in a message");
        };
    }

    private static String field(Payload command, String name) {
        if (!(command instanceof RecordValue r) || !r.has(name)) {
            throw new IllegalArgumentException("the template needs field '" + name + "' and the command has none: "
                    + command);
        }
        JsonNode f = r.get(name);
        return f.isTextual() ? f.textValue() : f.isNumber() ? number(f.doubleValue()) : f.toString();
    }

    private static String vector(double[] values) {
        StringBuilder b = new StringBuilder("[");
        for (int i = 0; i < values.length; i++) {
            b.append(i == 0 ? "" : ",").append(number(values[i]));
        }
        return b.append(']').toString();
    }

    static String number(double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("a command number must be finite, was " + v);
        }
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
