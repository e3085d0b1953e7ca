package org.habla.methods.virtual;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code link} record of {@code link-state}: whether the robot's link is up, whether that news is stale, and
 * since when.
 *
 * @param sinceMs     how long the link has been in its present state, as seen by the method
 * @param iface       the interface's id
 * @param connections each connection of the interface's driver, in its order, and whether it is up
 */
public record LinkStatus(boolean connected, boolean stale, long sinceMs, String iface, String detail,
        Map<String, Boolean> connections) implements RecordForm {

    /** The fields of a link-state record. */
    public static final RecordLayout<LinkStatus> LAYOUT = RecordLayout.of(LinkStatus.class)
            .flag("connected", LinkStatus::connected).doc("whether the robot's link is up")
            .flag("stale", LinkStatus::stale)
            .doc("whether the news is doubtful: it came marked stale, or no link record came for staleAfterMs")
            .longInteger("sinceMs", LinkStatus::sinceMs).unit("ms").doc("how long the link has been in this state")
            .text("interface", LinkStatus::iface).doc("the interface's id in the config")
            .text("detail", LinkStatus::detail).doc("what is down and why, or \"all connections up\"")
            .object("connections", LinkStatus::connectionsJson).doc("each connection of the driver: whether it is up")
            .build();

    public LinkStatus {
        connections = Collections.unmodifiableMap(new LinkedHashMap<>(connections));
    }

    @Override
    public RecordLayout<LinkStatus> layout() {
        return LAYOUT;
    }

    private JsonNode connectionsJson() {
        ObjectNode each = JsonNodeFactory.instance.objectNode();
        connections.forEach(each::put);
        return each;
    }
}
