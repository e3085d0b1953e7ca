package org.habla.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One client of the Foxglove WebSocket protocol ({@code foxglove.websocket.v1}). On connect it gets
 * {@code serverInfo} and the {@code advertise} of every method output; it may {@code subscribe} and
 * {@code unsubscribe}. The monitor's thread {@link #pump}s each subscription's new samples to it as binary
 * message-data frames:
 *
 * <pre>
 *   0x01 | subscription id: uint32 LE | receive time: uint64 LE, ns since the epoch | the channel's JSON message
 * </pre>
 *
 * A client that reads slower than its subscriptions produce has at most {@link #MAX_BACKLOG_BYTES} in flight;
 * beyond that its samples are dropped, counted and told once in a {@code status} warning.
 */
public final class FoxgloveSocket implements Session.Listener.AutoDemanding {

    /** The protocol's subprotocol name. */
    public static final String SUBPROTOCOL = "foxglove.websocket.v1";
    /** The most bytes written to one client and not yet taken by it. */
    static final long MAX_BACKLOG_BYTES = 8L * 1024 * 1024;
    /** The most subscriptions one client may hold. */
    static final int MAX_SUBSCRIPTIONS = 1_024;

    private static final Logger LOG = LoggerFactory.getLogger(FoxgloveSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final byte MESSAGE_DATA = 0x01;

    private record Subscription(FoxgloveChannel channel, long[] cursor) {
    }

    private final FoxgloveServer server;
    private final Map<Integer, Subscription> subscriptions = new ConcurrentHashMap<>();
    private final AtomicLong backlog = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private volatile boolean toldDrops;
    private volatile Session session;

    FoxgloveSocket(FoxgloveServer server) {
        this.server = server;
    }

    @Override
    public void onWebSocketOpen(Session s) {
        session = s;
        sendText(server.serverInfo());
        sendText(server.advertise());
        server.join(this);
    }

    @Override
    public void onWebSocketText(String message) {
        JsonNode m;
        try {
            m = JSON.readTree(message);
        } catch (Exception e) {
            status(2, "not JSON: " + e.getMessage());
            return;
        }
        switch (m.path("op").asText()) {
            case "subscribe" -> {
                for (JsonNode s : m.path("subscriptions")) {
                    FoxgloveChannel c = server.channel(s.path("channelId").asInt(-1));
                    if (c == null) {
                        status(1, "no channel " + s.path("channelId"));
                    } else if (subscriptions.size() >= MAX_SUBSCRIPTIONS) {
                        status(2, "at most " + MAX_SUBSCRIPTIONS + " subscriptions (FoxgloveSocket.MAX_SUBSCRIPTIONS)");
                    } else {
                        // A new subscription starts with the newest sample, not the history.
                        OutputHistory.Seen latest = server.history().latest(c.output().producer());
                        subscriptions.put(s.path("id").asInt(), new Subscription(c,
                                new long[] {latest == null ? 0 : latest.sample().sequence() - 1}));
                    }
                }
            }
            case "unsubscribe" -> m.path("subscriptionIds").forEach(id -> subscriptions.remove(id.asInt()));
            case "advertise", "unadvertise" -> {
                if (!server.publishing().allowed()) {
                    status(2, "client publishing is off: HABLA's Foxglove server is read-only until clients "
                            + "can hold the command role");
                }
            }
            default -> status(1, "operation '" + m.path("op").asText() + "' is not supported");
        }
    }

    @Override
    public void onWebSocketBinary(ByteBuffer payload, org.eclipse.jetty.websocket.api.Callback callback) {
        callback.succeed();
        if (!server.publishing().allowed()) {
            status(2, "client publishing is off");
        }
    }

    @Override
    public void onWebSocketClose(int statusCode, String reason) {
        server.leave(this);
    }

    @Override
    public void onWebSocketError(Throwable cause) {
        LOG.debug("foxglove client: {}", cause.toString());
        server.leave(this);
    }

    /** Sends every subscription's samples that are new since the last pump (the monitor's thread). */
    void pump(OutputHistory history) {
        Session s = session;
        if (s == null || !s.isOpen()) {
            return;
        }
        for (Map.Entry<Integer, Subscription> e : subscriptions.entrySet()) {
            Subscription sub = e.getValue();
            List<OutputHistory.Seen> fresh = history.since(sub.channel().output().producer(), sub.cursor()[0]);
            for (OutputHistory.Seen seen : fresh) {
                sub.cursor()[0] = seen.sample().sequence();
                if (backlog.get() > MAX_BACKLOG_BYTES) {
                    dropped.incrementAndGet();
                    continue;
                }
                byte[] body;
                try {
                    body = sub.channel().encode(seen.sample());
                } catch (Exception ex) {
                    dropped.incrementAndGet();
                    continue;
                }
                ByteBuffer frame = ByteBuffer.allocate(13 + body.length).order(ByteOrder.LITTLE_ENDIAN);
                frame.put(MESSAGE_DATA).putInt(e.getKey()).putLong(seen.seenMicros() * 1_000).put(body).flip();
                long size = frame.remaining();
                backlog.addAndGet(size);
                s.sendBinary(frame, Callback.from(() -> backlog.addAndGet(-size), ex -> backlog.addAndGet(-size)));
            }
        }
        if (dropped.get() > 0 && !toldDrops) {
            toldDrops = true;
            status(1, "this client reads slower than its subscriptions produce: samples are dropped");
        }
    }

    long dropped() {
        return dropped.get();
    }

    private void status(int level, String message) {
        ObjectNode m = JSON.createObjectNode().put("op", "status").put("level", level).put("message", message);
        sendText(m.toString());
    }

    private void sendText(String text) {
        Session s = session;
        if (s != null && s.isOpen()) {
            s.sendText(text, Callback.NOOP);
        }
    }

}
