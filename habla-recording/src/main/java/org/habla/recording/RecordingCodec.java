package org.habla.recording;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.driver.ChannelDescriptor;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.SampleCodec;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * Turns recorded events into frames of the control codec and back. A sample's value is written exactly as a
 * control socket writes it ({@link SampleCodec}), next to the fields that say where and when it was seen.
 */
final class RecordingCodec {

    static final String FORMAT = "habla-recording";
    static final int VERSION = 1;

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private RecordingCodec() {
    }

    static Frame header(RecordingHeader h) {
        ObjectNode n = NODES.objectNode().put("type", "recording").put("format", FORMAT).put("version", VERSION)
                .put("t", h.startMicros()).put("timeScale", h.timeScale()).put("configDir", h.configDir());
        n.set("config", h.config());
        ObjectNode ifs = n.putObject("interfaces");
        h.interfaces().forEach((id, channels) -> {
            ArrayNode a = ifs.putArray(id);
            for (ChannelDescriptor c : channels) {
                ObjectNode cn = a.addObject().put("name", c.name())
                        .put("direction", c.direction().name().toLowerCase(java.util.Locale.ROOT))
                        .put("kind", c.kind().wireName()).put("unit", c.unit()).put("motion", c.motion());
                cn.set("metadata", c.metadata());
            }
        });
        return Frame.of(n);
    }

    static RecordingHeader header(Frame f) throws RecordingException {
        ObjectNode h = f.header();
        if (!"recording".equals(h.path("type").asText()) || !FORMAT.equals(h.path("format").asText())) {
            throw new RecordingException("not a HABLA recording: the first record is not a \"recording\" header");
        }
        if (h.path("version").asInt() != VERSION) {
            throw new RecordingException("recording format version " + h.path("version") + " is not "
                    + VERSION + ", the one this HABLA reads");
        }
        if (!(h.get("config") instanceof ObjectNode config)) {
            throw new RecordingException("the recording's header carries no config");
        }
        Map<String, List<ChannelDescriptor>> interfaces = new LinkedHashMap<>();
        try {
            for (Map.Entry<String, JsonNode> e : h.path("interfaces").properties()) {
                List<ChannelDescriptor> list = new ArrayList<>();
                for (JsonNode c : e.getValue()) {
                    list.add(new ChannelDescriptor(c.path("name").asText(),
                            ChannelDescriptor.Direction.valueOf(c.path("direction").asText().toUpperCase(java.util.Locale.ROOT)),
                            PayloadKind.fromWire(c.path("kind").asText()), c.path("unit").asText(""),
                            c.path("motion").asBoolean(), c.get("metadata") instanceof ObjectNode m ? m : null));
                }
                interfaces.put(e.getKey(), list);
            }
        } catch (IllegalArgumentException e) {
            throw new RecordingException("the recording's header has a bad channel: " + e.getMessage());
        }
        return new RecordingHeader(h.path("t").asLong(), h.path("timeScale").asDouble(1), config,
                h.path("configDir").asText(""), interfaces);
    }

    static Frame frame(RecordedEvent e) {
        return switch (e) {
            case RecordedEvent.Reading r -> sample(base("reading", r.t()).put("iface", r.iface())
                    .put("channel", r.channel()), r.sample());
            case RecordedEvent.Command c -> sample(base("command", c.t()).put("iface", c.iface())
                    .put("channel", c.channel()).put("sent", c.sent()), c.sample());
            case RecordedEvent.ControlWrite w -> sample(base("control", w.t()).put("socket", w.socket())
                    .put("input", w.input()), w.sample());
            case RecordedEvent.Output o -> sample(base("output", o.t()).put("method", o.method())
                    .put("output", o.output()), o.sample());
            case RecordedEvent.LinkChange l -> Frame.of(base("link", l.t()).put("iface", l.iface()).put("up", l.up()));
            case RecordedEvent.WriterLeft w -> Frame.of(base("left", w.t()).put("socket", w.socket()));
            case RecordedEvent.Tick k -> Frame.of(base("tick", k.t()).put("task", k.task()).put("handled", k.handled()));
            case RecordedEvent.Skip k -> Frame.of(base("skip", k.t()).put("method", k.method()).put("input", k.input())
                    .put("arrival", k.arrival()));
            case RecordedEvent.Dropped d -> Frame.of(base("dropped", d.t()).put("total", d.total()));
            case RecordedEvent.Audit a -> Frame.of((ObjectNode) base("audit", a.t()).set("entry", a.entry()));
            case RecordedEvent.End x -> Frame.of(base("end", x.t()).put("written", x.written())
                    .put("dropped", x.dropped()));
        };
    }

    /**
     * The event a frame holds; null for a record type this HABLA does not know (a newer writer's), which a
     * reader skips.
     */
    static RecordedEvent event(Frame f) throws RecordingException {
        ObjectNode h = f.header();
        long t = h.path("t").asLong();
        try {
            return switch (h.path("type").asText()) {
                case "reading" -> new RecordedEvent.Reading(t, text(h, "iface"), text(h, "channel"),
                        sample(f, "@" + text(h, "iface") + "." + text(h, "channel")));
                case "command" -> new RecordedEvent.Command(t, text(h, "iface"), text(h, "channel"),
                        sample(f, h.path("producer").asText("")), h.path("sent").asBoolean());
                case "control" -> new RecordedEvent.ControlWrite(t, text(h, "socket"), text(h, "input"),
                        sample(f, "control:" + text(h, "socket")));
                case "output" -> new RecordedEvent.Output(t, text(h, "method"), text(h, "output"),
                        sample(f, text(h, "method") + "." + text(h, "output")));
                case "link" -> new RecordedEvent.LinkChange(t, text(h, "iface"), h.path("up").asBoolean());
                case "left" -> new RecordedEvent.WriterLeft(t, text(h, "socket"));
                case "tick" -> new RecordedEvent.Tick(t, text(h, "task"), h.path("handled").asLong(-1));
                case "skip" -> new RecordedEvent.Skip(t, text(h, "method"), text(h, "input"), h.path("arrival").asLong());
                case "dropped" -> new RecordedEvent.Dropped(t, h.path("total").asLong());
                case "audit" -> new RecordedEvent.Audit(t, h.get("entry") instanceof ObjectNode o ? o
                        : NODES.objectNode());
                case "end" -> new RecordedEvent.End(t, h.path("written").asLong(), h.path("dropped").asLong());
                default -> null;
            };
        } catch (FrameException e) {
            throw new RecordingException("a " + h.path("type").asText() + " record has a bad value: " + e.getMessage());
        }
    }

    private static ObjectNode base(String type, long t) {
        return NODES.objectNode().put("type", type).put("t", t);
    }

    private static Frame sample(ObjectNode header, Sample s) {
        header.put("producer", s.producer()).put("seq", s.sequence()).put("src", s.sourceMicros())
                .put("stale", s.stale());
        return SampleCodec.withValue(header, s.payload());
    }

    private static Sample sample(Frame f, String defaultProducer) throws FrameException {
        ObjectNode h = f.header();
        return new Sample(SampleCodec.value(f, PayloadKind.ANY), h.path("producer").asText(defaultProducer),
                h.path("seq").asLong(), h.path("src").asLong(), h.path("stale").asBoolean());
    }

    private static String text(ObjectNode h, String field) throws RecordingException {
        JsonNode n = h.get(field);
        if (n == null || !n.isTextual()) {
            throw new RecordingException("a " + h.path("type").asText() + " record has no \"" + field + "\"");
        }
        return n.textValue();
    }
}
