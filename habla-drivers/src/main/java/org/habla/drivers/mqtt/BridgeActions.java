package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import org.habla.bridge.CommandRole;
import org.habla.method.Input;
import org.habla.net.ClientId;
import org.habla.net.ControlLease;
import org.habla.net.ControlPoint;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.SampleCodec;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.TextValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What an {@code mqtt} bridge does with the messages it takes from the broker, for the sockets of its command role:
 *
 * <pre>
 *   ROOT/SOCKET/set, ROOT/SOCKET/INPUT/set   a value for a control input     (as a client's write)
 *   ROOT/SOCKET/take                         the bridge commands the socket   (as a client's {"op":"take"})
 *   ROOT/SOCKET/release                      the bridge gives control back    (as {"op":"release"}: the robot stops)
 * </pre>
 *
 * A retained message is never acted on: it is an old order the broker hands every new subscriber, and would move
 * the robot again at every start of the daemon. It is counted and said once per topic in the log. A refusal goes
 * to {@code ROOT/SOCKET/error} and, like every action, to the audit log.
 *
 * <p>The bridge is one commander ({@code mqtt-bridge} and its broker) under the socket's rule of one commander at
 * a time; it cannot disconnect as a client does, so it keeps control only for its hold time after its last action
 * or take, however long the socket's own lapse is (see {@link ControlLease.Client#holdMillis}).
 */
final class BridgeActions {

    private static final Logger LOG = LoggerFactory.getLogger(BridgeActions.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** The longest part of a refused payload the error message repeats. */
    private static final int MAX_ECHO_CHARS = 200;

    /** Publishes a message on a topic, not retained; never waits. */
    interface Sender {
        void send(String topic, String payload);
    }

    private final String root;
    private final Map<String, ControlPoint> points;
    private final CommandRole role;
    private final ControlLease.Client commander;
    private final Sender sender;
    private final Set<String> retainedSeen = ConcurrentHashMap.newKeySet();
    final LongAdder taken = new LongAdder();
    final LongAdder refused = new LongAdder();
    final LongAdder retainedIgnored = new LongAdder();

    BridgeActions(String root, Map<String, ControlPoint> points, CommandRole role, ClientId id, long holdMillis,
            Sender sender) {
        this.root = root;
        this.points = points;
        this.role = role;
        this.sender = sender;
        this.commander = new ControlLease.Client() {
            @Override
            public ClientId id() {
                return id;
            }

            @Override
            public long holdMillis() {
                return holdMillis;
            }
        };
    }

    ControlLease.Client commander() {
        return commander;
    }

    /** A message on one of the bridge's subscribed action topics. */
    void onMessage(String topic, String text, boolean retained) {
        if (retained) {
            retainedIgnored.increment();
            if (retainedSeen.add(topic)) {
                LOG.warn("bridge: a retained message on {} was ignored: actions are never taken from retained messages "
                        + "(clear it with: mosquitto_pub -r -n -t '{}')", topic, topic);
            }
            return;
        }
        String[] levels = topic.substring(root.length() + 1).split("/");
        String socket = levels[0];
        ControlPoint p = points.get(socket);
        if (p == null || !role.mayCommand(socket)) {
            refuse(socket, null, "not_allowed", "this bridge takes no actions for socket '" + socket + "'", text);
            return;
        }
        if (levels.length == 2 && (levels[1].equals("take") || levels[1].equals("release"))) {
            control(p, levels[1].equals("take"), text);
        } else {
            write(p, levels.length == 3 ? levels[1] : null, text);
        }
    }

    private void control(ControlPoint p, boolean take, String text) {
        Optional<ControlLease> lease = p.lease();
        if (lease.isEmpty()) {
            refuse(p.name(), null, "no_control", "socket '" + p.name() + "' moves nothing: it has no control to "
                    + (take ? "take" : "release"), text);
            return;
        }
        try {
            if (take) {
                lease.get().take(commander);
            } else {
                lease.get().release(commander);
            }
            role.audit(commander.id(), p.name(), take ? "take" : "release", text, null);
        } catch (ControlPoint.Rejected e) {
            refuse(p.name(), take ? "take" : "release", e.code(), e.getMessage(), text);
        }
    }

    private void write(ControlPoint p, String inputName, String text) {
        String socket = p.name();
        Input<?> input = null;
        for (Input<?> in : p.controlInputs()) {
            if (inputName == null ? p.controlInputs().size() == 1 : in.name().equals(inputName)) {
                input = in;
            }
        }
        if (input == null) {
            refuse(socket, inputName, "unknown_input", inputName == null ? "socket '" + socket + "' has "
                    + p.controlInputs().size() + " control inputs: name one in the topic (" + root + "/" + socket
                    + "/INPUT/set)" : "socket '" + socket + "' has no control input '" + inputName + "'", text);
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
            taken.increment();
            role.audit(commander.id(), socket, in.name(), text, null);
        } catch (FrameException e) {
            refuse(socket, input.name(), e.code(), e.getMessage(), text);
        } catch (ControlPoint.Rejected e) {
            refuse(socket, input.name(), e.code(), e.getMessage(), text);
        }
    }

    /** The payload as the input's value: JSON where it parses, else the text itself; a text input takes the text. */
    private static Payload value(Input<?> input, String text) throws FrameException {
        JsonNode node = parse(text);
        if (input.kind() == PayloadKind.TEXT) {
            return new TextValue(node != null && node.isTextual() ? node.textValue() : text);
        }
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

    private void refuse(String socket, String input, String code, String message, String payload) {
        refused.increment();
        role.audit(commander.id(), socket, input, payload, code + ": " + message);
        sender.send(root + "/" + MqttBridge.topicLevel(socket) + "/error", JsonNodeFactory.instance.objectNode()
                .put("type", "error").put("code", code).put("message", message)
                .put("payload", payload.length() > MAX_ECHO_CHARS ? payload.substring(0, MAX_ECHO_CHARS) : payload)
                .toString());
    }
}
