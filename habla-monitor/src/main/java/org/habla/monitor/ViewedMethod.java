package org.habla.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.Base64;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.habla.graph.OutputInfo;
import org.habla.method.Shape;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordField;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * What one page is shown of the method it selected, update by update: for each output the new points of its
 * plot (numbers, vector elements, a record's number fields), its last value, the last texts and recognised
 * phrases, the audio level, and the newest camera frame with the blobs found in it. Remembers what it already
 * sent, so each update carries only what is new; it runs on the monitor's thread.
 */
final class ViewedMethod {

    /** The most vector elements plotted as lines. */
    static final int MAX_PLOTTED_ELEMENTS = 16;
    /** The last texts (and phrases) listed per output. */
    static final int TEXTS_KEPT = 10;
    /** A page gets a new camera frame at most this often. */
    static final long IMAGE_PERIOD_MICROS = 200_000;

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private final String methodId;
    private final List<OutputInfo> outputs;
    /** The image output the method reads, whose frames its blobs are drawn over (or null). */
    private final String imageSource;
    private final Map<String, Long> sentSequence = new HashMap<>();
    private long imageSentAtMicros;
    private long imageSentSequence;

    ViewedMethod(String methodId, List<OutputInfo> outputs, String imageSource) {
        this.methodId = methodId;
        this.outputs = List.copyOf(outputs);
        this.imageSource = imageSource;
    }

    String methodId() {
        return methodId;
    }

    /** The update for this tick: everything new since the previous one. */
    ObjectNode update(OutputHistory history, long nowMicros) {
        ObjectNode u = JSON.objectNode().put("type", "detail").put("method", methodId);
        ObjectNode outs = u.putObject("outputs");
        for (OutputInfo info : outputs) {
            String producer = info.producer();
            List<OutputHistory.Seen> fresh = history.since(producer, sentSequence.getOrDefault(producer, 0L));
            ObjectNode o = outs.putObject(producer);
            o.put("kind", info.shape().kind().wireName());
            if (fresh.isEmpty()) {
                continue;
            }
            sentSequence.put(producer, fresh.get(fresh.size() - 1).sample().sequence());
            OutputHistory.Seen last = fresh.get(fresh.size() - 1);
            o.put("count", last.sample().sequence());
            o.put("stale", last.sample().stale());
            ArrayNode points = JSON.arrayNode();
            ArrayNode texts = JSON.arrayNode();
            for (OutputHistory.Seen s : fresh) {
                double t = s.seenMicros() / 1e6;
                switch (s.sample().payload()) {
                    case NumberValue n -> points.add(JSON.arrayNode().add(t).add(finite(n.value())));
                    case VectorValue v -> {
                        ArrayNode p = JSON.arrayNode().add(t);
                        for (int i = 0; i < Math.min(v.size(), MAX_PLOTTED_ELEMENTS); i++) {
                            p.add(finite(v.get(i)));
                        }
                        points.add(p);
                    }
                    case RecordValue r -> {
                        ArrayNode p = recordPoint(t, r);
                        if (p != null) {
                            points.add(p);
                        }
                        phrase(r, texts);
                    }
                    case TextValue text -> texts.add(JSON.objectNode().put("t", t).put("text", text.text()));
                    case AudioChunk a -> o.put("levelDb", levelDb(a));
                    case ImageFrame f -> { }
                }
            }
            if (!points.isEmpty()) {
                o.set("points", points);
                o.set("series", series(last.sample().payload(), info.shape()));
            }
            if (!texts.isEmpty()) {
                o.set("texts", tail(texts));
            }
            o.set("last", lastValue(last.sample().payload()));
            if (last.sample().payload() instanceof RecordValue r && r.get("blobs").isArray()) {
                o.set("blobs", r.json());
            }
        }
        image(history, nowMicros, u);
        return u;
    }

    /** The newest frame of the camera this method shows (its own image output, or the one it reads). */
    private void image(OutputHistory history, long nowMicros, ObjectNode u) {
        String producer = outputs.stream().filter(o -> o.shape().kind().wireName().equals("image"))
                .map(OutputInfo::producer).findFirst().orElse(imageSource);
        if (producer == null || nowMicros - imageSentAtMicros < IMAGE_PERIOD_MICROS) {
            return;
        }
        OutputHistory.Seen s = history.latest(producer);
        if (s == null || s.sample().sequence() == imageSentSequence
                || !(s.sample().payload() instanceof ImageFrame frame)) {
            return;
        }
        imageSentAtMicros = nowMicros;
        imageSentSequence = s.sample().sequence();
        try {
            ViewableImage img = ViewableImage.of(frame);
            u.putObject("image").put("producer", producer).put("width", img.width()).put("height", img.height())
                    .put("src", "data:" + img.mimeType() + ";base64," + Base64.getEncoder().encodeToString(img.bytes()));
        } catch (IOException e) {
            u.putObject("image").put("producer", producer).put("error", e.getMessage());
        }
    }

    /** The names of the plotted lines of a payload; a record's declared fields with their units. */
    private static ArrayNode series(Payload p, Shape shape) {
        ArrayNode names = JSON.arrayNode();
        switch (p) {
            case NumberValue n -> names.add("value");
            case VectorValue v -> {
                for (int i = 0; i < Math.min(v.size(), MAX_PLOTTED_ELEMENTS); i++) {
                    names.add("[" + i + "]");
                }
            }
            case RecordValue r -> r.jsonView().properties().forEach(e -> {
                if (e.getValue().isNumber()) {
                    String unit = shape.recordFields().stream().filter(f -> f.name().equals(e.getKey()))
                            .map(RecordField::unit).findFirst().orElse("");
                    names.add(unit.isEmpty() ? e.getKey() : e.getKey() + " [" + unit + "]");
                }
            });
            default -> { }
        }
        return names;
    }

    private static ArrayNode recordPoint(double t, RecordValue r) {
        ArrayNode p = JSON.arrayNode().add(t);
        r.jsonView().properties().forEach(e -> {
            if (e.getValue().isNumber()) {
                p.add(finite(e.getValue().doubleValue()));
            }
        });
        return p.size() > 1 ? p : null;
    }

    /** A recognised phrase with its confidence (or score), from a speech result record. */
    private static void phrase(RecordValue r, ArrayNode texts) {
        JsonNode phrase = r.get("phrase");
        if (phrase.isTextual()) {
            ObjectNode o = texts.addObject().put("text", phrase.asText());
            for (String measure : new String[] {"confidence", "score"}) {
                if (r.get(measure).isNumber()) {
                    o.put(measure, r.get(measure).doubleValue());
                }
            }
        }
    }

    private static JsonNode lastValue(Payload p) {
        return switch (p) {
            case NumberValue n -> JSON.numberNode(n.value());
            case VectorValue v -> {
                ArrayNode a = JSON.arrayNode();
                for (double d : v.toArray()) {
                    a.add(finite(d));
                }
                yield a;
            }
            case TextValue t -> JSON.textNode(t.text());
            case RecordValue r -> r.json();
            case AudioChunk a -> JSON.textNode(a.frameCount() + " frames at " + a.format().sampleRateHz() + " Hz");
            case ImageFrame f -> JSON.textNode(f.width() + "×" + f.height() + " " + f.encoding());
        };
    }

    /** The RMS level of a chunk's first channel in dB below full scale (−120 for silence). */
    static double levelDb(AudioChunk a) {
        double[] x = a.channel(0);
        if (x.length == 0) {
            return -120;
        }
        double sum = 0;
        for (double v : x) {
            sum += v * v;
        }
        double rms = Math.sqrt(sum / x.length);
        return rms <= 1e-6 ? -120 : Math.max(-120, 20 * Math.log10(rms));
    }

    private static ArrayNode tail(ArrayNode texts) {
        ArrayNode out = JSON.arrayNode();
        for (int i = Math.max(0, texts.size() - TEXTS_KEPT); i < texts.size(); i++) {
            out.add(texts.get(i));
        }
        return out;
    }

    private static JsonNode finite(double d) {
        return Double.isFinite(d) ? JSON.numberNode(d) : JSON.nullNode();
    }
}
