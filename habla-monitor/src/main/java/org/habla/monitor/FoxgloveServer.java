package org.habla.monitor;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CopyOnWriteArraySet;
import org.habla.graph.OutputInfo;

/**
 * The Foxglove WebSocket protocol on the monitor's port: every method output is a channel, so Foxglove or
 * Lichtblick connected to {@code ws://HOST:PORT} sees the whole graph live. Read-only unless a
 * {@link FoxglovePublishing} allows otherwise. Samples are pumped to the clients from the monitor's thread.
 */
final class FoxgloveServer {

    /** How often the clients get their subscriptions' new samples. */
    static final long PUMP_PERIOD_MS = 20;
    /** The most Foxglove clients at once; another is refused with 503. */
    static final int MAX_CLIENTS = 16;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final List<FoxgloveChannel> channels = new ArrayList<>();
    private final Set<FoxgloveSocket> clients = new CopyOnWriteArraySet<>();
    private final OutputHistory history;
    private final FoxglovePublishing publishing;
    private final String serverInfo;
    private final String advertise;

    FoxgloveServer(List<OutputInfo> outputs, OutputHistory history, FoxglovePublishing publishing, String name,
            MonitorHub hub) {
        this.history = history;
        this.publishing = publishing;
        for (OutputInfo o : outputs) {
            channels.add(FoxgloveChannel.of(channels.size() + 1, o));
        }
        ObjectNode info = JSON.createObjectNode().put("op", "serverInfo").put("name", name);
        ArrayNode caps = info.putArray("capabilities");
        if (publishing.allowed()) {
            caps.add("clientPublish");
            info.putArray("supportedEncodings").add("json");
        }
        info.putObject("metadata").put("habla", "HABLA daemon " + name);
        info.put("sessionId", UUID.randomUUID().toString());
        serverInfo = info.toString();
        ObjectNode adv = JSON.createObjectNode().put("op", "advertise");
        ArrayNode list = adv.putArray("channels");
        channels.forEach(c -> list.add(c.advertisement()));
        advertise = adv.toString();
        hub.every(PUMP_PERIOD_MS, this::pump);
    }

    String serverInfo() {
        return serverInfo;
    }

    String advertise() {
        return advertise;
    }

    OutputHistory history() {
        return history;
    }

    FoxglovePublishing publishing() {
        return publishing;
    }

    FoxgloveChannel channel(int id) {
        return id >= 1 && id <= channels.size() ? channels.get(id - 1) : null;
    }

    int clientCount() {
        return clients.size();
    }

    void join(FoxgloveSocket c) {
        clients.add(c);
    }

    void leave(FoxgloveSocket c) {
        clients.remove(c);
    }

    private void pump() {
        for (FoxgloveSocket c : clients) {
            c.pump(history);
        }
    }
}
