// Over 300 lines, on purpose: one broker connection's traffic, out and in, shares its client and its counters.
package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.hivemq.client.mqtt.MqttClient;
import com.hivemq.client.mqtt.MqttClientSslConfigBuilder;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5ClientBuilder;
import com.hivemq.client.mqtt.mqtt5.message.publish.Mqtt5Publish;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import org.habla.bridge.Bridge;
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
 * way, they are dropped and counted. The connection is kept by the client library, reconnecting with a doubling
 * wait; on every (re)connection the bridge says it is online, publishes its discovery configs and each socket's
 * staleness and subscribes again. Losing the broker is the bridge's leaving: where it commanded, the robot stops.
 */
final class MqttBridge implements Bridge {

    /** Messages handed to the client library and not yet sent; more are dropped. */
    static final int MAX_IN_FLIGHT = 4096;
    /** The shortest and longest waits before connecting to the broker again. */
    private static final long RECONNECT_MIN_MILLIS = 200;
    private static final long RECONNECT_MAX_MILLIS = 5_000;
    /** How often client and broker check each other when nothing flows. */
    private static final int KEEP_ALIVE_S = 5;
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
    private final LongAdder connects = new LongAdder();
    private final String version = version();
    private volatile Mqtt5AsyncClient client;
    private volatile BridgeActions actions;
    private HomeAssistantDiscovery discovery;
    private String root;
    private String system;

    MqttBridge(InterfaceAddress address, MqttBridgeParams params) {
        this.address = address;
        this.params = params;
        this.commanderId = new ClientId("mqtt-bridge", address.toString());
    }

    @Override
    public void start(String systemName, List<ControlPoint> exposed, CommandRole commandRole) throws IOException {
        this.system = systemName;
        this.root = params.baseTopic() + "/" + topicLevel(systemName);
        this.discovery = new HomeAssistantDiscovery(params.discoveryPrefix(), root, systemName);
        for (ControlPoint p : exposed) {
            if (params.sockets().contains(p.name())) {
                points.put(p.name(), p);
            }
        }
        this.actions = new BridgeActions(root, points, commandRole, commanderId, params.holdMs(),
                (topic, payload) -> send(topic, payload, false, true));
        String password = BrokerLogin.password(params.password(), params.passwordFile());
        Optional<BrokerEndpoint.Tls> tls = BrokerLogin.tls(params.tls(), params.caFile());
        String id = params.clientId().isEmpty()
                ? "habla-bridge-" + topicLevel(systemName) + "-" + UUID.randomUUID().toString().substring(0, 6)
                : params.clientId();
        Mqtt5ClientBuilder b = MqttClient.builder().useMqttVersion5().identifier(id).serverHost(address.host())
                .serverPort(address.portOr(params.tls() ? MqttDriver.DEFAULT_TLS_PORT : MqttDriver.DEFAULT_PORT))
                .automaticReconnect().initialDelay(RECONNECT_MIN_MILLIS, TimeUnit.MILLISECONDS)
                .maxDelay(RECONNECT_MAX_MILLIS, TimeUnit.MILLISECONDS).applyAutomaticReconnect()
                .addConnectedListener(c -> announce(commandRole))
                .addDisconnectedListener(c -> lost(c.getCause()));
        if (tls.isPresent()) {
            MqttClientSslConfigBuilder.Nested<? extends Mqtt5ClientBuilder> ssl = b.sslConfig();
            if (tls.get().trust() != null) {
                ssl = ssl.trustManagerFactory(tls.get().trust());
            }
            b = ssl.applySslConfig();
        }
        Mqtt5AsyncClient c = b.buildAsync();
        client = c;
        c.publishes(MqttGlobalPublishFilter.SUBSCRIBED, this::arrived);
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
        var connect = c.connectWith().cleanStart(true).keepAlive(KEEP_ALIVE_S);
        if (!params.username().isEmpty()) {
            connect = connect.simpleAuth().username(params.username()).password(password.getBytes(StandardCharsets.UTF_8))
                    .applySimpleAuth();
        }
        connect.willPublish().topic(root + "/availability").payload(bytes("offline")).qos(MqttQos.AT_LEAST_ONCE)
                .retain(true).applyWillPublish().send().whenComplete((ack, e) -> {
                    if (e != null) {
                        LOG.warn("bridge {}: the broker at {} is not there yet ({}); trying again", system, address,
                                e.getMessage());
                    }
                });
        LOG.info("bridge to MQTT broker {}: publishing {} on {}/…, actions from {}", address, params.publish(), root,
                params.actions());
    }

    /** On every (re)connection: online, discovery, staleness, subscriptions. Runs on the client library's thread. */
    private void announce(CommandRole role) {
        connects.increment();
        Mqtt5AsyncClient c = client;
        send(root + "/availability", "online", true, true);
        sayAgain();
        for (String socket : params.actions()) {
            if (role.mayCommand(socket)) {
                String level = root + "/" + topicLevel(socket);
                for (String filter : List.of(level + "/set", level + "/+/set", level + "/take", level + "/release")) {
                    c.subscribeWith().topicFilter(filter).qos(MqttQos.AT_LEAST_ONCE).send();
                }
            }
        }
        if (params.discovery()) {
            c.subscribeWith().topicFilter(params.discoveryPrefix() + "/status").qos(MqttQos.AT_LEAST_ONCE).send();
        }
        LOG.info("bridge to {} connected", address);
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
    private void lost(Throwable cause) {
        LOG.debug("bridge to {} disconnected: {}", address, cause.toString());
        BridgeActions a = actions;
        if (a != null) {
            points.values().forEach(p -> p.lease().ifPresent(l -> l.left(a.commander())));
        }
    }

    private void arrived(Mqtt5Publish message) {
        String topic = message.getTopic().toString();
        String text = new String(message.getPayloadAsBytes(), StandardCharsets.UTF_8);
        if (topic.equals(params.discoveryPrefix() + "/status")) {
            if (text.strip().equals("online")) {
                LOG.info("bridge: Home Assistant is online; discovery, states and staleness said again");
                sayAgain();
            }
            return;
        }
        actions.onMessage(topic, text, message.isRetain());
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
        Mqtt5AsyncClient c = client;
        if (c == null || !c.getState().isConnected() || !always && inFlight.get() >= MAX_IN_FLIGHT) {
            if (!always) {
                dropped.increment();
            }
            return;
        }
        inFlight.incrementAndGet();
        c.publishWith().topic(topic).payload(bytes(payload)).retain(retain)
                .qos(retain ? MqttQos.AT_LEAST_ONCE : MqttQos.AT_MOST_ONCE).send().whenComplete((r, e) -> {
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
        Mqtt5AsyncClient c = client;
        BridgeActions a = actions;
        ObjectNode n = JsonNodeFactory.instance.objectNode().put("type", "mqtt").put("broker", address.toString())
                .put("connected", c != null && c.getState().isConnected()).put("connects", connects.sum())
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

    @Override
    public void close() {
        BridgeActions a = actions;
        if (a != null) {
            points.values().forEach(p -> p.lease().ifPresent(l -> l.left(a.commander())));
        }
        subscriptions.forEach(ControlPoint.Subscription::close);
        subscriptions.clear();
        Mqtt5AsyncClient c = client;
        client = null;
        if (c != null) {
            try {
                if (c.getState().isConnected()) {
                    c.publishWith().topic(root + "/availability").payload(bytes("offline")).retain(true)
                            .qos(MqttQos.AT_LEAST_ONCE).send().get(CLOSE_WAIT_MILLIS, TimeUnit.MILLISECONDS);
                }
                c.disconnect().get(CLOSE_WAIT_MILLIS, TimeUnit.MILLISECONDS);
            } catch (Exception e) {
                LOG.debug("bridge disconnect: {}", e.toString());
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
