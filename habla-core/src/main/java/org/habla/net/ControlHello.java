package org.habla.net;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.method.Shape;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordField;
import org.habla.security.PortAccess;

/**
 * The hello line of a control socket (docs/control-contract.md): what the socket carries — its method, layer and
 * direction, each output's kind, unit, fields and meaning (a record's declared fields each with its unit, frame and
 * meaning in {@code fieldInfo}), each control input — whether it is stale, who commands it, and the limits a client
 * must keep to. An output that hands on what feeds it (a pass-through) is described as that source.
 */
final class ControlHello {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private ControlHello() {
    }

    /** The hello of a socket that requires authentication, before the client has authenticated. */
    static Frame authRequired(ControlPoint point, Limits limits) {
        ObjectNode h = NODES.objectNode()
                .put("type", "hello")
                .put("protocol", ControlProtocol.PROTOCOL)
                .put("socket", point.name())
                .put("auth", "required");
        h.putObject("limits").put("maxLineBytes", limits.maxLineBytes())
                .put("idleTimeoutMs", limits.idleTimeoutMs());
        return Frame.of(h);
    }

    /**
     * The whole hello; with the client's name and role once it has authenticated ({@code who} null on an open
     * port), and who commands the socket where {@code lease} is not null.
     */
    static Frame full(ControlPoint point, Limits limits, ControlLease lease, PortAccess.Admitted who) {
        ObjectNode h = NODES.objectNode()
                .put("type", "hello")
                .put("protocol", ControlProtocol.PROTOCOL)
                .put("socket", point.name())
                .put("method", point.methodId())
                .put("layer", point.layer().configName())
                .put("direction", direction(point))
                .put("auth", who == null ? "off" : "ok");
        if (who != null) {
            h.put("client", who.principal().name()).put("role", who.role().fileName());
        }
        ArrayNode outputs = h.putArray("outputs");
        for (Output<?> o : point.outputs()) {
            Shape shape = point.shapeOf(o);
            ObjectNode out = outputs.addObject()
                    .put("name", o.name())
                    .put("kind", (o.kind() == PayloadKind.ANY ? shape.kind() : o.kind()).wireName())
                    .put("unit", shape.unit());
            shape.fields().forEach(out.putArray("fields")::add);
            out.put("doc", shape.doc());
            if (!shape.recordFields().isEmpty()) {
                ArrayNode info = out.putArray("fieldInfo");
                for (RecordField f : shape.recordFields()) {
                    info.addObject().put("name", f.name()).put("type", f.type()).put("unit", f.unit())
                            .put("frame", f.frame()).put("doc", f.doc()).put("optional", f.optional());
                }
            }
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

    private static String direction(ControlPoint point) {
        boolean out = !point.outputs().isEmpty();
        boolean in = !point.controlInputs().isEmpty();
        return out && in ? "both" : in ? "in" : "out";
    }
}
