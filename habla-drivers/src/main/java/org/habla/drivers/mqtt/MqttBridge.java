package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
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
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.net.ClientId;
import org.habla.net.ControlLease;
import org.habla.net.ControlPoint;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.SampleCodec;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Exposed methods on an MQTT broker, beside their sockets, for every control architecture and home-automation
 * system that subscribes there:
 *
 * <pre>
 *   BASE/SYSTEM/availability          online | offline        retained; the broker says offline if the daemon dies
 *   BASE/SYSTEM/SOCKET                {"type":"sample","output":..,"seq":..,"t":..,"stale":..,"kind":..,"value":..}
 *   BASE/SYSTEM/SOCKET/stale          {"stale":true,"why":"interface robot is down"}
 *   BASE/SYSTEM/SOCKET/set       ◀──  a value for the socket's only control input (JSON, or plain text)
 *   BASE/SYSTEM/SOCKET/INPUT/set ◀──  a value for a named control input
 *   BASE/SYSTEM/SOCKET/error          {"code":"bad_value","message":..,"payload":..}   a refused action
 *   PREFIX/sensor/habla_SYSTEM_SOCKET_OUTPUT/config, PREFIX/text/habla_SYSTEM_SOCKET/config   discovery, retained
 * </pre>
 *
 * A sample line is the one the control socket sends; binary samples (audio, images) are not published. Actions
 * are taken only for the sockets of the bridge's command role, through the same checks as a socket's client and
 * under the same rule of one commander at a time: the bridge is one commander ({@code mqtt-bridge} and its
 * broker), so an action while a socket client commands the socket is refused as {@code busy} on the error topic,
 * and the bridge's leaving, when it commanded, stops the robot as a client's would.
 * Samples never wait: while the broker is away, or when more than {@link #MAX_IN_FLIGHT} messages are on their
 * way, they are dropped and counted. The connection is kept by the client library, reconnecting with a doubling
 * wait; on every (re)connection the bridge says it is online, publishes its discovery configs and subscribes again.
 */
final class MqttBridge implements Bridge {

    /** Messages handed to the client library and not yet sent; more are dropped. */
    static final int MAX_IN_FLIGHT = 4096;
    private static final Logger LOG = LoggerFactory.getLogger(MqttBridge.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    private final InterfaceAddress address;
    private final MqttBridgeParams params;
    private final Map<String, ControlPoint> points = new ConcurrentHashMap<>();
    /** The bridge as a commander of the sockets it writes to. */
    private final ControlLease.Client commander;
    private final Map<String, Long> lastSentNanos = new ConcurrentHashMap<>();
    private final List<ControlPoint.Subscription> subscriptions = new ArrayList<>();
    private final AtomicInteger inFlight = new AtomicInteger();
    private final LongAdder published = new LongAdder();
    private final LongAdder dropped = new LongAdder();
    private final LongAdder actions = new LongAdder();
    private final LongAdder refused = new LongAdder();
    private final LongAdder connects = new LongAdder();
    private volatile Mqtt5AsyncClient client;
    private volatile CommandRole role = CommandRole.NONE;
    private String root;
    private String system;

    MqttBridge(InterfaceAddress address, MqttBridgeParams params) {
        this.address = address;
        this.params = params;
        ClientId id = new ClientId("mqtt-bridge", address.toString());
        this.commander = () -> id;
    }

    @Override
    public void start(String systemName, List<ControlPoint> exposed, CommandRole commandRole) throws IOException {
        this.system = systemName;
        this.root = params.baseTopic() + "/" + topicLevel(systemName);
        this.role = commandRole;
        for (ControlPoint p : exposed) {
            if (params.sockets().contains(p.name())) {
                points.put(p.name(), p);
            }
        }
        String password = BrokerLogin.password(params.password(), params.passwordFile());
        Optional<BrokerEndpoint.Tls> tls = BrokerLogin.tls(params.tls(), params.caFile());
        String id = params.clientId().isEmpty()
                ? "habla-bridge-" + topicLevel(systemName) + "-" + UUID.randomUUID().toString().substring(0, 6)
                : params.clientId();
        Mqtt5ClientBuilder b = MqttClient.builder().useMqttVersion5().identifier(id).serverHost(address.host())
                .serverPort(address.portOr(params.tls() ? MqttDriver.DEFAULT_TLS_PORT : MqttDriver.DEFAULT_PORT))
                .automaticReconnect().initialDelay(200, TimeUnit.MILLISECONDS).maxDelay(5, TimeUnit.SECONDS)
                .applyAutomaticReconnect()
                .addConnectedListener(c -> announce())
                .addDisconnectedListener(c -> LOG.debug("bridge to {} disconnected: {}", address, c.getCause().toString()));
        if (tls.isPresent()) {
            MqttClientSslConfigBuilder.Nested<? extends Mqtt5ClientBuilder> ssl = b.sslConfig();
            if (tls.get().trust() != null) {
                ssl = ssl.trustManagerFactory(tls.get().trust());
            }
            b = ssl.applySslConfig();
        }
        Mqtt5AsyncClient c = b.buildAsync();
        client = c;
        c.publishes(MqttGlobalPublishFilter.SUBSCRIBED, this::onSet);
        for (String socket : params.publish()) {
            ControlPoint p = points.get(socket);
            subscriptions.add(p.subscribe(new ControlPoint.Listener() {
                @Override
                public void onSample(Output<?> output, Sample sample) {
                    publishSample(socket, output, sample);
                }

                @Override
                public void onStale(boolean stale, String why) {
                    send(root + "/" + socket + "/stale", JsonNodeFactory.instance.objectNode().put("stale", stale)
                            .put("why", why == null ? "" : why).toString(), false, true);
                }
            }));
        }
        var connect = c.connectWith().cleanStart(true).keepAlive(5);
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

    /** On every (re)connection: online, discovery, subscriptions. Runs on the client library's thread. */
    private void announce() {
        connects.increment();
        Mqtt5AsyncClient c = client;
        send(root + "/availability", "online", true, true);
        if (params.discovery()) {
            discovery();
        }
        for (String socket : params.actions()) {
            if (role.mayCommand(socket)) {
                c.subscribeWith().topicFilter(root + "/" + topicLevel(socket) + "/set").qos(MqttQos.AT_LEAST_ONCE).send();
                c.subscribeWith().topicFilter(root + "/" + topicLevel(socket) + "/+/set").qos(MqttQos.AT_LEAST_ONCE)
                        .send();
            }
        }
        LOG.info("bridge to {} connected", address);
    }

    private void discovery() {
        ObjectNode device = JSON.createObjectNode();
        device.putArray("identifiers").add("habla_" + topicLevel(system));
        device.put("name", "HABLA " + system).put("manufacturer", "HABLA").put("model", "HABLA daemon");
        for (String socket : params.publish()) {
            ControlPoint p = points.get(socket);
            for (Output<?> out : p.outputs()) {
                if (out.kind() == PayloadKind.AUDIO || out.kind() == PayloadKind.IMAGE) {
                    continue;
                }
                String id = "habla_" + topicLevel(system) + "_" + topicLevel(socket) + "_" + topicLevel(out.name());
                boolean plain = out.kind() == PayloadKind.NUMBER || out.kind() == PayloadKind.TEXT;
                ObjectNode c = JSON.createObjectNode().put("name", socket + " " + out.name()).put("unique_id", id)
                        .put("object_id", id).put("state_topic", root + "/" + socket)
                        .put("availability_topic", root + "/availability")
                        .put("value_template", "{{ value_json.value" + (plain ? "" : " | tojson | truncate(250)")
                                + " if value_json.output == '" + out.name() + "' else this.state }}");
                if (!out.shape().unit().isEmpty() && out.kind() == PayloadKind.NUMBER) {
                    c.put("unit_of_measurement", out.shape().unit());
                }
                c.set("device", device);
                send(params.discoveryPrefix() + "/sensor/" + id + "/config", c.toString(), true, true);
            }
        }
        for (String socket : params.actions()) {
            String id = "habla_" + topicLevel(system) + "_" + topicLevel(socket);
            ObjectNode c = JSON.createObjectNode().put("name", socket).put("unique_id", id).put("object_id", id)
                    .put("command_topic", root + "/" + socket + "/set").put("availability_topic", root + "/availability");
            c.set("device", device);
            send(params.discoveryPrefix() + "/text/" + id + "/config", c.toString(), true, true);
        }
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

    /** An action from a topic: to the socket's control input, if the command role allows it. */
    private void onSet(Mqtt5Publish message) {
        String topic = message.getTopic().toString();
        String[] levels = topic.substring(root.length() + 1).split("/");
        String socket = levels[0];
        String inputName = levels.length == 3 ? levels[1] : null;
        String text = new String(message.getPayloadAsBytes(), StandardCharsets.UTF_8);
        ControlPoint p = points.get(socket);
        if (p == null || !role.mayCommand(socket)) {
            refuse(socket, "not_allowed", "this bridge takes no actions for socket '" + socket + "'", text);
            role.audit(commander.id(), socket, inputName, text, "not_allowed: this bridge takes no actions for "
                    + "socket '" + socket + "'");
            return;
        }
        Input<?> input = null;
        for (Input<?> in : p.controlInputs()) {
            if (inputName == null ? p.controlInputs().size() == 1 : in.name().equals(inputName)) {
                input = in;
            }
        }
        if (input == null) {
            refuse(socket, "unknown_input", inputName == null ? "socket '" + socket + "' has "
                    + p.controlInputs().size() + " control inputs: name one in the topic (" + root + "/" + socket
                    + "/INPUT/set)" : "socket '" + socket + "' has no control input '" + inputName + "'", text);
            role.audit(commander.id(), socket, inputName, text, "unknown_input");
            return;
        }
        try {
            Input<?> in = input;
            Payload value = value(input, text);
            Optional<ControlLease> lease = p.lease();
            if (lease.isPresent()) {
                lease.get().write(commander, () -> p.write(in, value));
            } else {
                p.write(in, value);
            }
            actions.increment();
            role.audit(commander.id(), socket, in.name(), text, null);
        } catch (FrameException e) {
            refuse(socket, e.code(), e.getMessage(), text);
            role.audit(commander.id(), socket, input.name(), text, e.code() + ": " + e.getMessage());
        } catch (ControlPoint.Rejected e) {
            refuse(socket, e.code(), e.getMessage(), text);
            role.audit(commander.id(), socket, input.name(), text, e.code() + ": " + e.getMessage());
        }
    }

    /** The payload as the input's value: JSON where it parses, else the text itself; a text input takes the text. */
    private static Payload value(Input<?> input, String text) throws FrameException {
        if (input.kind() == PayloadKind.TEXT) {
            JsonNode node = parse(text);
            return new TextValue(node != null && node.isTextual() ? node.textValue() : text);
        }
        JsonNode node = parse(text);
        ObjectNode header = JsonNodeFactory.instance.objectNode();
        header.set("value", node == null ? JsonNodeFactory.instance.textNode(text) : node);
        return SampleCodec.value(Frame.of(header), input.kind());
    }

    private static JsonNode parse(String text) {
        try {
            return JSON.readTree(text);
        } catch (IOException e) {
            return null;
        }
    }

    private void refuse(String socket, String code, String message, String payload) {
        refused.increment();
        send(root + "/" + topicLevel(socket) + "/error", JsonNodeFactory.instance.objectNode().put("type", "error")
                .put("code", code).put("message", message)
                .put("payload", payload.length() > 200 ? payload.substring(0, 200) : payload).toString(), false, true);
    }

    @Override
    public ObjectNode status() {
        Mqtt5AsyncClient c = client;
        ObjectNode n = JsonNodeFactory.instance.objectNode().put("type", "mqtt").put("broker", address.toString())
                .put("connected", c != null && c.getState().isConnected()).put("connects", connects.sum())
                .put("published", published.sum()).put("dropped", dropped.sum()).put("actions", actions.sum())
                .put("refused", refused.sum());
        return n;
    }

    @Override
    public void close() {
        points.values().forEach(p -> p.lease().ifPresent(l -> l.left(commander)));
        subscriptions.forEach(ControlPoint.Subscription::close);
        subscriptions.clear();
        Mqtt5AsyncClient c = client;
        client = null;
        if (c != null) {
            try {
                if (c.getState().isConnected()) {
                    c.publishWith().topic(root + "/availability").payload(bytes("offline")).retain(true)
                            .qos(MqttQos.AT_LEAST_ONCE).send().get(2, TimeUnit.SECONDS);
                }
                c.disconnect().get(2, TimeUnit.SECONDS);
            } catch (Exception e) {
                LOG.debug("bridge disconnect: {}", e.toString());
            }
        }
    }

    /** A name as one topic level: what is not a letter, digit, '_' or '-' becomes '_'. */
    static String topicLevel(String name) {
        return name.replaceAll("[^A-Za-z0-9_-]", "_");
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
