package org.habla.net;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Map;
import org.habla.config.Limits;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/**
 * The control protocol {@code habla-control/1} of one connection: the hello line, and the answer to each
 * request a client sends. Knows nothing of sockets: it reads frames and hands replies to a {@link Replies}.
 *
 * <pre>
 *   client                                      server
 *   {"op":"write","input":"action","value":..}  -&gt; ok (if "id") | error
 *   {"value":..}                                -&gt; the same, to the only control input
 *   {"op":"latest"}                             -&gt; one sample line per output that has one, then ok (if "id")
 *   {"op":"rate","maxHz":5}                     -&gt; ok (if "id"); samples thinned to 5 a second per output
 *   {"op":"ping"}                               -&gt; {"type":"pong"} (with the "id", which acknowledges it)
 *   {"op":"take"}                               -&gt; ok (if "id"); this client commands the socket now
 *   {"op":"release"}                            -&gt; ok (if "id") | error not_commander; the robot is stopped
 * </pre>
 *
 * On an actuating socket a write goes through the socket's {@link ControlLease}: one commander at a time.
 */
final class ControlProtocol {

    static final String PROTOCOL = "habla-control/1";

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    /** Where the protocol's answers go, and the per-connection settings it changes; the client it serves. */
    interface Replies extends ControlLease.Client {
        void reply(Frame frame) throws InterruptedException;

        void rate(double maxHz);
    }

    private final ControlPoint point;
    private final Limits limits;
    private final ControlLease lease;

    /** @param lease who commands the socket; null when its values reach no actuator */
    ControlProtocol(ControlPoint point, Limits limits, ControlLease lease) {
        this.point = point;
        this.limits = limits;
        this.lease = lease;
    }

    /** The line a client gets on connect. */
    Frame hello() {
        ObjectNode h = NODES.objectNode()
                .put("type", "hello")
                .put("protocol", PROTOCOL)
                .put("socket", point.name())
                .put("method", point.methodId())
                .put("layer", point.layer().configName())
                .put("direction", direction());
        ArrayNode outputs = h.putArray("outputs");
        for (Output<?> o : point.outputs()) {
            ObjectNode out = outputs.addObject()
                    .put("name", o.name())
                    .put("kind", o.kind().wireName())
                    .put("unit", o.shape().unit());
            o.shape().fields().forEach(out.putArray("fields")::add);
            out.put("doc", o.shape().doc());
        }
        ArrayNode inputs = h.putArray("inputs");
        for (Input<?> i : point.controlInputs()) {
            inputs.addObject().put("name", i.name()).put("kind", i.kind().wireName());
        }
        h.put("stale", point.stale());
        if (lease != null) {
            h.set("control", lease.status());
        }
        h.putObject("limits")
                .put("maxLineBytes", limits.maxLineBytes())
                .put("maxBinaryBytes", limits.maxBinaryBytes())
                .put("clientQueueSamples", limits.clientQueueSamples())
                .put("idleTimeoutMs", limits.idleTimeoutMs())
                .put("frameTimeoutMs", limits.frameTimeoutMs());
        return Frame.of(h);
    }

    private String direction() {
        boolean out = !point.outputs().isEmpty();
        boolean in = !point.controlInputs().isEmpty();
        return out && in ? "both" : in ? "in" : "out";
    }

    /** Answers one request. */
    void handle(Frame request, Replies replies) throws InterruptedException {
        ObjectNode h = request.header();
        JsonNode id = h.get("id");
        String op = h.has("op") ? h.get("op").asText() : h.has("value") || request.hasBody() ? "write" : "";
        try {
            switch (op) {
                case "write" -> write(request, replies);
                case "latest" -> latest(replies);
                case "rate" -> rate(h, replies);
                case "take" -> commanded().take(replies);
                case "release" -> commanded().release(replies);
                case "ping" -> {
                    ObjectNode pong = NODES.objectNode().put("type", "pong");
                    if (id != null) {
                        pong.set("id", id);
                    }
                    replies.reply(Frame.of(pong));
                    return;
                }
                default -> throw FrameException.recoverable("unknown_op", (op.isEmpty()
                        ? "a request needs \"op\" (or a \"value\" to write)"
                        : "unknown op '" + op + "'") + "; ops are write, latest, rate, ping");
            }
            if (id != null) {
                ObjectNode ok = NODES.objectNode().put("type", "ok");
                ok.set("id", id);
                replies.reply(Frame.of(ok));
            }
        } catch (FrameException e) {
            replies.reply(error(e.code(), e.getMessage(), id));
        } catch (ControlPoint.Rejected e) {
            String code = e.code() == null || e.code().isBlank() ? "rejected" : e.code();
            replies.reply(error(code, e.getMessage(), id));
        }
    }

    private void write(Frame request, Replies replies) throws FrameException, ControlPoint.Rejected {
        List<Input<?>> inputs = point.controlInputs();
        if (inputs.isEmpty()) {
            throw FrameException.recoverable("read_only", "socket '" + point.name() + "' takes no values");
        }
        JsonNode named = request.header().get("input");
        Input<?> input;
        if (named == null) {
            if (inputs.size() != 1) {
                throw FrameException.recoverable("unknown_input", "name the \"input\": one of " + names(inputs));
            }
            input = inputs.get(0);
        } else {
            input = inputs.stream().filter(i -> i.name().equals(named.asText())).findFirst()
                    .orElseThrow(() -> FrameException.recoverable("unknown_input",
                            "no input " + named + "; inputs are " + names(inputs)));
        }
        Payload value = SampleCodec.value(request, input.kind());
        if (lease == null) {
            point.write(input, value);
        } else {
            lease.write(replies, () -> point.write(input, value));
        }
    }

    /** The client has gone: if it commanded the socket, control is free and the robot is stopped. */
    void left(ControlLease.Client client) {
        if (lease != null) {
            lease.left(client);
        }
    }

    private ControlLease commanded() throws FrameException {
        if (lease == null) {
            throw FrameException.recoverable("no_control", "socket '" + point.name()
                    + "' moves nothing: there is no control to take or release");
        }
        return lease;
    }

    private void latest(Replies replies) throws InterruptedException {
        Map<String, Sample> latest = point.latest();
        for (Output<?> o : point.outputs()) {
            Sample s = latest.get(o.name());
            if (s != null) {
                replies.reply(SampleCodec.sampleFrame(o.name(), s));
            }
        }
    }

    private static void rate(ObjectNode h, Replies replies) throws FrameException {
        JsonNode maxHz = h.get("maxHz");
        if (maxHz == null || !maxHz.isNumber() || !(maxHz.doubleValue() >= 0) || maxHz.doubleValue() > 1e6) {
            throw FrameException.badValue("\"maxHz\" must be a number in [0, 1000000] (0: no limit), was " + maxHz);
        }
        replies.rate(maxHz.doubleValue());
    }

    /** An error line. */
    static Frame error(String code, String message, JsonNode id) {
        ObjectNode e = NODES.objectNode().put("type", "error").put("code", code).put("message", message);
        if (id != null) {
            e.set("id", id);
        }
        return Frame.of(e);
    }

    private static List<String> names(List<Input<?>> inputs) {
        return inputs.stream().map(Input::name).toList();
    }
}
