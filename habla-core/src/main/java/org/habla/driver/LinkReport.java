package org.habla.driver;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The record the engine sends on every interface's {@code link} channel ({@link Driver#LINK_CHANNEL}): whether the
 * link is up, which interface it is, what is down, and each connection's state.
 *
 * <pre>{@code {"up": true, "interface": "robot", "detail": "all connections up", "connections": {"arcos": true}}}</pre>
 *
 * @param up          whether every connection the interface needs is up
 * @param iface       the interface's id in the config
 * @param detail      what is down and why, or {@code "all connections up"}
 * @param connections each of the driver's connections, in the driver's order, and whether it is up
 */
public record LinkReport(boolean up, String iface, String detail, Map<String, Boolean> connections)
        implements RecordForm {

    public static final RecordLayout<LinkReport> LAYOUT = RecordLayout.of(LinkReport.class)
            .flag("up", LinkReport::up).doc("whether every connection the interface needs is up")
            .text("interface", LinkReport::iface).doc("the interface's id in the config")
            .text("detail", LinkReport::detail).doc("what is down and why, or \"all connections up\"")
            .object("connections", LinkReport::connectionsJson).doc("each connection of the driver: whether it is up")
            .build();

    public LinkReport {
        connections = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(connections));
    }

    @Override
    public RecordLayout<LinkReport> layout() {
        return LAYOUT;
    }

    private JsonNode connectionsJson() {
        ObjectNode each = JsonNodeFactory.instance.objectNode();
        connections.forEach(each::put);
        return each;
    }

    /**
     * The report a link record carries: the form itself from this daemon's engine, else read from its JSON (a
     * recording); empty when the record has no boolean {@code up}.
     */
    public static Optional<LinkReport> fromRecord(RecordValue record) {
        Optional<LinkReport> typed = record.form(LinkReport.class);
        if (typed.isPresent()) {
            return typed;
        }
        JsonNode up = record.get("up");
        if (!up.isBoolean()) {
            return Optional.empty();
        }
        Map<String, Boolean> each = new LinkedHashMap<>();
        record.get("connections").fields().forEachRemaining(e -> each.put(e.getKey(), e.getValue().asBoolean()));
        JsonNode iface = record.get("interface");
        JsonNode detail = record.get("detail");
        return Optional.of(new LinkReport(up.booleanValue(), iface.isTextual() ? iface.asText() : "",
                detail.isTextual() ? detail.asText() : "", each));
    }
}
