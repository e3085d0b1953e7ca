// Over 300 lines, on purpose: one broker connection's traffic, out and in, shares its client and its counters.
package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import org.habla.bridge.Bridge;
import org.habla.bridge.BridgeSession;
import org.habla.bridge.CommandRole;
import org.habla.driver.InterfaceAddress;
import org.habla.method.Output;
import org.habla.net.ClientId;
import org.habla.net.ControlPoint;
import org.habla.net.Frame;
import org.habla.net.SampleCodec;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Exposed methods on an MQTT broker, beside their sockets, for every control architecture and home-automation
 * system that subscribes there:
 *
 * <pre>
 *   BASE/SYSTEM/availability          online | offline        retained; the broker says offline if the daemon dies
 *   BASE/SYSTEM/SOCKET                {"type":"sample","output":..,"seq":..,"t":..,"stale":..,"kind":..,"value":..}
 *   BASE/SYSTEM/SOCKET/stale          {"stale":true,"why":"interface robot is down"}   retained, and on every connection
 *   BASE/SYSTEM/SOCKET/OUTPUT/state   {"value":..,"t":"2026-05-01T10:00:00Z"}   retained, with discovery (see below)
 *   BASE/SYSTEM/SOCKET/set       ◀──  a value for the socket's only control input (JSON, or plain text)
 *   BASE/SYSTEM/SOCKET/INPUT/set ◀──  a value for a named control input
 *   BASE/SYSTEM/SOCKET/take      ◀──  the bridge takes command of the socket; /release gives it back
 *   BASE/SYSTEM/SOCKET/control        {"type":"control","holder":..,"why":..}   retained: who commands the socket
 *   BASE/SYSTEM/SOCKET/error          {"code":"bad_value","message":..,"payload":..}   a refused action
 *   PREFIX/sensor/.., PREFIX/text/..  Home Assistant discovery, retained ({@link HomeAssistantDiscovery})
 *   PREFIX/status                ◀──  Home Assistant's "online": discovery, states and staleness are said again
 * </pre>
 *
 * A sample line is the one the control socket sends; binary samples (audio, images) are not published. Actions
 * are taken only for the sockets of the bridge's command role ({@link BridgeActions}), never from a retained
 * message, through the same checks as a socket's client and under the same rule of one commander at a time.
 * Samples never wait: while the broker is away, or when more than {@link #MAX_IN_FLIGHT} messages are on their
 * way, they are dropped and counted. The connection is the engine's to keep, as every link's is: each attempt is a
 * fresh {@link BridgeSession} over an {@link MqttWire} (whose last will says offline), retried with the bridge's
 * {@code reconnect} back-off; on every (re)connection the bridge says it is online, publishes its discovery configs
 * and each socket's staleness and subscribes again. Losing the broker is the bridge's leaving: where it commanded,
 * the robot stops.
 */
final class MqttBridge implements Bridge {

    /** Messages handed to the client library and not yet sent; more are dropped. */
    static final int MAX_IN_FLIGHT = 4096;
    /** How often client and broker check each other when nothing flows. */
    private static final int KEEP_ALIVE_S = 5;
    private static final int QOS_AT_MOST_ONCE = 0;
    private static final int QOS_AT_LEAST_ONCE = 1;
    /** How long a stop waits for the goodbye to reach the broker. */
    private static final long CLOSE_WAIT_MILLIS = 2_000;
    private static final Logger LOG = LoggerFactory.getLogger(MqttBridge.class);

    private final InterfaceAddress address;
    private final MqttBridgeParams params;
    private final Map<String, ControlPoint> points = new ConcurrentHashMap<>();
    private final ClientId commanderId;
    private final Map<String, Long> lastSentNanos = new ConcurrentHashMap<>();
    /** Why each published socket last turned stale; also the lock that keeps its retained staleness in order. */
    private final Map<String, String> staleWhy = new HashMap<>();
    private final List<ControlPoint.Subscription> subscriptions = new ArrayList<>();
    private final AtomicInteger inFlight = new AtomicInteger();
    private final LongAdder published = new LongAdder();
    private final LongAdder dropped = new LongAdder();
    private final String version = version();
    /** The session that is connected and announced, or null while the broker is away. */
    private volatile Session live;
    private volatile BridgeActions actions;
    private HomeAssistantDiscovery discovery;
    private CommandRole role;
    private BrokerEndpoint endpoint;
    private String root;

    MqttBridge(InterfaceAddress address, MqttBridgeParams params) {
        this.address = address;
        this.params = params;
        this.commanderId = new ClientId("mqtt-bridge", address.toString());
    }

    @Override
    public void start(String systemName, List<ControlPoint> exposed, CommandRole commandRole) throws IOException {
        this.root = params.baseTopic() + "/" + topicLevel(systemName);
        this.discovery = new HomeAssistantDiscovery(params.discoveryPrefix(), root, systemName);
        for (ControlPoint p : exposed) {
            if (params.sockets().contains(p.name())) {
                points.put(p.name(), p);
            }
        }
        this.actions = new BridgeActions(root, points, commandRole, commanderId, params.holdMs(),
                (topic, payload) -> send(topic, payload, false, true));
        this.role = commandRole;
        String id = params.clientId().isEmpty()
                ? "habla-bridge-" + topicLevel(systemName) + "-" + UUID.randomUUID().toString().substring(0, 6)
                : params.clientId();
        this.endpoint = new BrokerEndpoint(address.host(),
                address.portOr(params.tls() ? MqttDriver.DEFAULT_TLS_PORT : MqttDriver.DEFAULT_PORT),
                BrokerEndpoint.MqttVersion.V5, id, params.username(),
                BrokerLogin.password(params.password(), params.passwordFile()), BrokerLogin.tls(params.tls(), params.caFile()),
                KEEP_ALIVE_S, Optional.of(new BrokerEndpoint.Will(root + "/availability", bytes("offline"), true)));
        for (ControlPoint p : points.values()) {
            String socket = p.name();
            boolean published = params.publish().contains(socket);
            subscriptions.add(p.subscribe(new ControlPoint.Listener() {
                @Override
                public void onSample(Output<?> output, Sample sample) {
                    if (published) {
                        publishSample(socket, output, sample);
                    }
                }

                @Override
                public void onStale(boolean stale, String why) {
                    if (published) {
                        synchronized (staleWhy) {
                            staleWhy.put(socket, why == null ? "" : why);
                            publishStale(socket, stale, why);
                        }
                    }
                }

                @Override
                public void onControl(Frame line) {
                    send(root + "/" + topicLevel(socket) + "/control", line.header().toString(), true, true);
                }
            }));
        }
        LOG.info("bridge to MQTT broker {}: publishing {} on {}/…, actions from {}", address, params.publish(), root,
                params.actions());
    }

    @Override
    public BridgeSession session() {
        return new Session();
    }

    /** The topic filters the bridge listens to: actions for its command role, and Home Assistant's birth. */
    private List<String> subscriptions() {
        List<String> filters = new ArrayList<>();
        for (String socket : params.actions()) {
            if (role.mayCommand(socket)) {
                String level = root + "/" + topicLevel(socket);
                filters.addAll(List.of(level + "/set", level + "/+/set", level + "/take", level + "/release"));
            }
        }
        if (params.discovery()) {
            filters.add(params.discoveryPrefix() + "/status");
        }
        return filters;
    }

    /** Discovery, each socket's staleness, newest values and commander: at connection and when Home Assistant starts. */
    private void sayAgain() {
        for (String socket : params.publish()) {
            ControlPoint p = points.get(socket);
            synchronized (staleWhy) {
                boolean stale = p.stale();
                publishStale(socket, stale, stale ? staleWhy.getOrDefault(socket, "") : "");
            }
            if (params.discovery()) {
                Map<String, Sample> latest = p.latest();
                for (Output<?> out : p.outputs()) {
                    Sample sample = latest.get(out.name());
                    if (sample != null && HomeAssistantDiscovery.carried(out.kind())) {
                        send(discovery.stateTopic(socket, out.name()), HomeAssistantDiscovery.state(sample), true, true);
                    }
                }
            }
        }
        for (ControlPoint p : points.values()) {
            p.lease().ifPresent(l -> send(root + "/" + topicLevel(p.name()) + "/control",
                    l.status().put("type", "control").toString(), true, true));
        }
        if (params.discovery()) {
            publishDiscovery();
        }
    }

    private void publishDiscovery() {
        for (String socket : params.publish()) {
            ControlPoint p = points.get(socket);
            List<Output<?>> outputs = p.outputs().stream().filter(o -> HomeAssistantDiscovery.carried(o.kind())).toList();
            for (Output<?> out : outputs) {
                send(discovery.sensorTopic(socket, out.name()), discovery.sensor(socket, out.name(), outputs.size(),
                        out.kind(), out.shape().unit(), version).toString(), true, true);
            }
        }
        for (String socket : params.actions()) {
            send(discovery.textTopic(socket), discovery.text(socket, version).toString(), true, true);
        }
    }

    /** The broker is lost: the bridge has left, and gives up any control it held (the robot stops). */
    private void left() {
        BridgeActions a = actions;
        if (a != null) {
            points.values().forEach(p -> p.lease().ifPresent(l -> l.left(a.commander())));
        }
    }

    /** A message on a subscribed topic. Runs on the client library's thread. */
    private void arrived(String topic, byte[] payload, boolean retained) {
        String text = new String(payload, StandardCharsets.UTF_8);
        if (topic.equals(params.discoveryPrefix() + "/status")) {
            if (text.strip().equals("online")) {
                LOG.info("bridge: Home Assistant is online; discovery, states and staleness said again");
                sayAgain();
            }
            return;
        }
        actions.onMessage(topic, text, retained);
    }

    private void publishStale(String socket, boolean stale, String why) {
        send(root + "/" + topicLevel(socket) + "/stale", JsonNodeFactory.instance.objectNode().put("stale", stale)
                .put("why", why == null ? "" : why).toString(), true, true);
    }

    private void publishSample(String socket, Output<?> output, Sample sample) {
        if (params.maxHz() > 0) {
            long now = System.nanoTime();
            String key = socket + "/" + output.name();
            Long last = lastSentNanos.get(key);
            if (last != null && now - last < (long) (1e9 / params.maxHz())) {
                return;
            }
            lastSentNanos.put(key, now);
        }
        Frame f = SampleCodec.sampleFrame(output.name(), sample);
        if (f.hasBody()) {
            return;
        }
        send(root + "/" + socket, f.header().toString(), false, false);
        if (params.discovery()) {
            send(discovery.stateTopic(socket, output.name()), HomeAssistantDiscovery.state(sample), true, false);
        }
    }

    /** Hands a message to the client library, or drops and counts it; never waits. */
    private void send(String topic, String payload, boolean retain, boolean always) {
        Session s = live;
        if (s == null || !always && inFlight.get() >= MAX_IN_FLIGHT) {
            if (!always) {
                dropped.increment();
            }
            return;
        }
        inFlight.incrementAndGet();
        s.wire.publish(topic, bytes(payload), retain ? QOS_AT_LEAST_ONCE : QOS_AT_MOST_ONCE, retain).whenComplete((r, e) -> {
                    inFlight.decrementAndGet();
                    if (e == null) {
                        published.increment();
                    } else {
                        dropped.increment();
                    }
                });
    }

    @Override
    public ObjectNode status() {
        BridgeActions a = actions;
        ObjectNode n = JsonNodeFactory.instance.objectNode().put("type", "mqtt").put("broker", address.toString())
                .put("published", published.sum()).put("dropped", dropped.sum())
                .put("actions", a == null ? 0 : a.taken.sum()).put("refused", a == null ? 0 : a.refused.sum())
                .put("retainedIgnored", a == null ? 0 : a.retainedIgnored.sum());
        var commands = n.putArray("commands");
        for (ControlPoint p : points.values()) {
            p.lease().ifPresent(l -> {
                JsonNode holder = l.status().path("holder");
                if (holder.path("connection").asText().equals(commanderId.connection())
                        && holder.path("address").asText().equals(commanderId.address())) {
                    commands.add(p.name());
                }
            });
        }
        return n;
    }

    /** Called by the engine once its link is stopped (its session said offline and disconnected). */
    @Override
    public void close() {
        left();
        subscriptions.forEach(ControlPoint.Subscription::close);
        subscriptions.clear();
    }

    /**
     * One connection to the broker: a fresh {@link MqttWire} whose last will says offline, announced on opening.
     * Actions arrive on the client library's threads; {@link #readNext} waits until the connection is lost.
     */
    private final class Session implements BridgeSession {

        private final CountDownLatch ended = new CountDownLatch(1);
        private volatile MqttWire wire;
        private volatile Throwable lost;

        @Override
        public void open(Duration timeout) throws IOException {
            MqttWire w = MqttWire.to(endpoint, cause -> {
                lost = cause == null ? new IOException("connection lost") : cause;
                ended.countDown();
            });
            wire = w;
            if (ended.getCount() == 0) {
                w.disconnect();
                throw new IOException("closed");
            }
            w.connect(timeout);
            live = this;
            send(root + "/availability", "online", true, true);
            sayAgain();
            List<String> filters = subscriptions();
            if (!filters.isEmpty()) {
                w.subscribe(filters, QOS_AT_LEAST_ONCE, MqttBridge.this::arrived, timeout);
            }
            LOG.debug("bridge to {} connected and announced", address);
        }

        @Override
        public void readNext() throws IOException {
            try {
                ended.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new InterruptedIOException("interrupted");
            }
            Throwable t = lost;
            throw new IOException("the broker connection was lost: "
                    + (t == null ? "closed" : t.getMessage() == null ? t.toString() : t.getMessage()));
        }

        @Override
        public void goodbye() {
            MqttWire w = wire;
            try {
                w.publish(root + "/availability", bytes("offline"), QOS_AT_LEAST_ONCE, true)
                        .get(CLOSE_WAIT_MILLIS, TimeUnit.MILLISECONDS);
            } catch (Exception e) {
                LOG.debug("bridge goodbye: {}", e.toString());
            }
        }

        @Override
        public void close() {
            boolean wasLive = live == this;
            if (wasLive) {
                live = null;
                left();
            }
            ended.countDown();
            MqttWire w = wire;
            if (w != null) {
                w.disconnect();
            }
        }
    }

    /** A name as one topic level: what is not a letter, digit, '_' or '-' becomes '_'. */
    static String topicLevel(String name) {
        return name.replaceAll("[^A-Za-z0-9_-]", "_");
    }

    /** The HABLA version in the jar's manifest, or "development" when run from classes. */
    private static String version() {
        String v = MqttBridge.class.getPackage().getImplementationVersion();
        return v == null ? "development" : v;
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
