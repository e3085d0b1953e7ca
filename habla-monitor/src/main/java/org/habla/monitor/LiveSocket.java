package org.habla.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The page's WebSocket ({@code /live}): the monitor writes status and detail updates, one in flight at a time;
 * the page writes only {@code {"select":"METHOD"}}. Anything else gets an error message and changes nothing:
 * the page cannot drive the robot.
 */
public final class LiveSocket implements Session.Listener.AutoDemanding, Viewer {

    private static final Logger LOG = LoggerFactory.getLogger(LiveSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    private final MonitorHub hub;
    private final AtomicBoolean inFlight = new AtomicBoolean();
    private final AtomicLong skipped = new AtomicLong();
    private volatile Session session;
    private volatile String selected;

    LiveSocket(MonitorHub hub) {
        this.hub = hub;
    }

    @Override
    public void onWebSocketOpen(Session s) {
        session = s;
        hub.join(this);
    }

    @Override
    public void onWebSocketText(String message) {
        try {
            JsonNode m = JSON.readTree(message);
            if (m.isObject() && m.size() == 1 && m.path("select").isTextual()) {
                selected = m.get("select").asText();
                return;
            }
        } catch (Exception e) {
            // answered below, as any other line the page may not send
        }
        Session s = session;
        if (s != null) {
            s.sendText("{\"type\":\"error\",\"code\":\"read_only\",\"message\":"
                    + "\"the monitor only takes {\\\"select\\\": METHOD}\"}", Callback.NOOP);
        }
    }

    @Override
    public void onWebSocketClose(int statusCode, String reason) {
        hub.leave(this);
    }

    @Override
    public void onWebSocketError(Throwable cause) {
        LOG.debug("monitor page: {}", cause.toString());
        hub.leave(this);
    }

    @Override
    public boolean busy() {
        return inFlight.get();
    }

    @Override
    public boolean offer(String text) {
        Session s = session;
        if (s == null || !s.isOpen() || !inFlight.compareAndSet(false, true)) {
            skipped.incrementAndGet();
            return false;
        }
        s.sendText(text, Callback.from(() -> inFlight.set(false), e -> {
            inFlight.set(false);
            LOG.debug("monitor page: {}", e.toString());
        }));
        return true;
    }

    @Override
    public String selected() {
        return selected;
    }
}
