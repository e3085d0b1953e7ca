package org.habla.net;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Collection;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * The lines a daemon and a {@code habla worker} exchange to run one method on the worker's computer. Same
 * framing as every HABLA socket ({@link FrameReader}): one JSON object per line, audio and images as
 * {@code "bytes": N} binary blocks after the line. One TCP connection carries one placed method.
 *
 * <pre>
 *   daemon                                              worker
 *     |  &lt;-- {"type":"hello","protocol":"habla-worker/1","types":["speech-recognition",...]}
 *     |  --&gt; {"type":"place","method":"speech","methodType":"speech-recognition",
 *     |        "layer":"processing","params":{...},"channels":{},"commandChannels":{}}
 *     |  &lt;-- {"type":"placed","method":"speech","inputs":["segments"],"outputs":["words"]}
 *     |        or {"type":"error","code":"unknown_type","message":"..."} and the worker closes
 *     |  --&gt; {"type":"sample","input":"segments","seq":7,"t":MICROS,"stale":false,
 *     |        "kind":"audio","rateHz":16000,"channels":1,"bits":16,"bytes":N}  + N bytes of PCM
 *     |  &lt;-- {"type":"sample","output":"words","seq":3,"t":MICROS,"stale":false,"kind":"text","value":"go forward"}
 *     |  &lt;-- {"type":"heartbeat","ready":true,"readiness":""}   every second: silence means a lost worker
 *     |  &lt;-- {"type":"error","code":"bad_json",...}     a bad line costs that line only
 * </pre>
 *
 * A worker started with a secret (it must have one to listen beyond loopback) first has the daemon prove it
 * holds the same secret, and proves it back, before any place line ({@link org.habla.security.WorkerSecret}):
 *
 * <pre>
 *     |  &lt;-- {"type":"hello",...,"auth":"required","challenge":Cw}
 *     |  --&gt; {"type":"auth","challenge":Cd,"proof":HMAC(secret, daemon Cw Cd)}
 *     |  &lt;-- {"type":"trusted","proof":HMAC(secret, worker Cw Cd)}   or error auth_failed and the worker closes
 * </pre>
 *
 * {@code t} is the source time of the daemon's sample, carried through the worker unchanged, so a
 * sample's age is measured on the daemon's clock only.
 */
public final class WorkerProtocol {

    /** The protocol and version this build speaks; a worker of another version is refused. */
    public static final String PROTOCOL = "habla-worker/1";
    /** The port {@code habla worker} listens on unless told otherwise. */
    public static final int DEFAULT_PORT = 7600;
    /** How often a worker tells the daemon it is alive. */
    public static final long HEARTBEAT_MILLIS = 1_000;

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private WorkerProtocol() {
    }

    /** What a worker says on connect: the protocol version and the method types it can run. */
    public record Hello(String protocol, Set<String> types, String challenge) {

        public Hello {
            types = Set.copyOf(types);
        }

        public Hello(String protocol, Set<String> types) {
            this(protocol, types, null);
        }

        /** Whether the worker asks the daemon to prove the shared secret. */
        public boolean asksForSecret() {
            return challenge != null;
        }

        /** Reads a hello line; anything else is a protocol error. */
        public static Hello of(Frame frame) throws FrameException {
            if (!frame.type().equals("hello")) {
                throw FrameException.fatal("not_a_worker", "expected a worker's hello line, got "
                        + abbreviate(frame.header().toString()));
            }
            JsonNode protocol = frame.header().get("protocol");
            JsonNode types = frame.header().get("types");
            if (protocol == null || !protocol.isTextual() || types == null || !types.isArray()) {
                throw FrameException.fatal("bad_hello", "a worker's hello needs \"protocol\" and \"types\"");
            }
            Set<String> names = new TreeSet<>();
            types.forEach(t -> names.add(t.asText()));
            JsonNode challenge = frame.header().get("challenge");
            return new Hello(protocol.textValue(), names, challenge != null && challenge.isTextual()
                    ? challenge.textValue() : null);
        }

        /** Why this worker cannot run a method of {@code type}, or null when it can. */
        public String refusal(String type) {
            if (!protocol.equals(PROTOCOL)) {
                return "the worker speaks " + protocol + ", this daemon " + PROTOCOL;
            }
            if (!types.contains(type)) {
                return "the worker cannot run method type '" + type + "' (it runs: "
                        + (types.isEmpty() ? "nothing" : String.join(", ", new TreeSet<>(types))) + ")";
            }
            return null;
        }
    }

    public static ObjectNode hello(Collection<String> types) {
        ObjectNode h = NODES.objectNode().put("type", "hello").put("protocol", PROTOCOL);
        ArrayNode a = h.putArray("types");
        new TreeSet<>(types).forEach(a::add);
        return h;
    }

    /** The hello of a worker that has a secret: it asks the daemon to answer {@code challenge}. */
    public static ObjectNode hello(Collection<String> types, String challenge) {
        return hello(types).put("auth", "required").put("challenge", challenge);
    }

    /** The daemon's proof of the secret, and its own challenge to the worker. */
    public static ObjectNode auth(String daemonChallenge, String proof) {
        return NODES.objectNode().put("type", "auth").put("challenge", daemonChallenge).put("proof", proof);
    }

    /** The worker trusts the daemon, and proves the secret back. */
    public static ObjectNode trusted(String proof) {
        return NODES.objectNode().put("type", "trusted").put("proof", proof);
    }

    /**
     * The daemon's side of the proof: answers the worker's challenge and checks the worker's answer to its own.
     *
     * @param secret the daemon's worker secret, or null when it has none
     * @throws java.io.IOException saying why the worker is not to be trusted, or why it refused the daemon
     */
    public static void prove(Hello hello, org.habla.security.WorkerSecret secret, FrameReader reader,
            FrameWriter writer, String worker) throws java.io.IOException {
        if (!hello.asksForSecret()) {
            if (secret != null) {
                throw new java.io.IOException("worker " + worker + " does not ask for the shared secret, so it cannot "
                        + "prove it is the trusted worker: start it with --secret-file");
            }
            return;
        }
        if (secret == null) {
            throw new java.io.IOException("worker " + worker + " requires the shared secret: give \"workerSecret\" "
                    + "in the credentials file (security.credentials)");
        }
        String mine = org.habla.security.WorkerSecret.challenge();
        writer.send(auth(mine, secret.proof("daemon", hello.challenge(), mine)));
        Frame answer = reader.read();
        if (answer == null) {
            throw new java.io.IOException("worker " + worker + " closed the connection instead of answering the proof");
        }
        if (answer.type().equals("error")) {
            throw new java.io.IOException("worker " + worker + " does not trust this daemon: "
                    + answer.header().path("code").asText() + ": " + answer.header().path("message").asText());
        }
        if (!answer.type().equals("trusted") || !secret.verify(answer.header().path("proof").asText(null), "worker",
                hello.challenge(), mine)) {
            throw new java.io.IOException("worker " + worker + " did not prove the shared secret: it is not trusted");
        }
    }

    /**
     * Asks the worker to make and start one method; {@code channels} and {@code commandChannels} describe the
     * interface channels its inputs read and its outputs write (port name → channel), so the method sees
     * the same metadata (sonar poses, speed limits) as in the daemon.
     */
    public static ObjectNode place(String methodId, String methodType, String layer, ObjectNode params,
            Map<String, ChannelDescriptor> channels, Map<String, ChannelDescriptor> commandChannels) {
        ObjectNode h = NODES.objectNode().put("type", "place").put("method", methodId).put("methodType", methodType)
                .put("layer", layer);
        h.set("params", params);
        ObjectNode ch = h.putObject("channels");
        channels.forEach((port, c) -> ch.set(port, channel(c)));
        ObjectNode cc = h.putObject("commandChannels");
        commandChannels.forEach((port, c) -> cc.set(port, channel(c)));
        return h;
    }

    /** A channel description as JSON. */
    public static ObjectNode channel(ChannelDescriptor c) {
        ObjectNode n = NODES.objectNode().put("name", c.name())
                .put("direction", c.direction().name().toLowerCase(java.util.Locale.ROOT))
                .put("kind", c.kind().wireName()).put("unit", c.unit()).put("motion", c.motion());
        n.set("metadata", c.metadata());
        return n;
    }

    /** Reads the channel descriptions of a place line's {@code field} (port name → channel). */
    public static Map<String, ChannelDescriptor> channels(Frame place, String field) throws FrameException {
        Map<String, ChannelDescriptor> out = new LinkedHashMap<>();
        JsonNode node = place.header().get(field);
        if (node == null) {
            return out;
        }
        if (!node.isObject()) {
            throw FrameException.badValue("\"" + field + "\" must be an object of port name -> channel");
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            JsonNode c = e.getValue();
            try {
                out.put(e.getKey(), new ChannelDescriptor(c.path("name").asText(null),
                        ChannelDescriptor.Direction.valueOf(c.path("direction").asText("").toUpperCase(java.util.Locale.ROOT)),
                        PayloadKind.fromWire(c.path("kind").asText("")), c.path("unit").asText(""),
                        c.path("motion").asBoolean(false),
                        c.get("metadata") instanceof ObjectNode m ? m : null));
            } catch (IllegalArgumentException ex) {
                throw FrameException.badValue("channel of port '" + e.getKey() + "': " + ex.getMessage());
            }
        }
        return out;
    }

    /** The worker's answer once the method runs: its port names. */
    public static ObjectNode placed(String methodId, List<String> inputs, List<String> outputs) {
        ObjectNode h = NODES.objectNode().put("type", "placed").put("method", methodId);
        inputs.forEach(h.putArray("inputs")::add);
        outputs.forEach(h.putArray("outputs")::add);
        return h;
    }

    public static ObjectNode error(String code, String message) {
        return NODES.objectNode().put("type", "error").put("code", code).put("message", message);
    }

    /** The worker's "still here", with whether the method can do its work yet (e.g. its model is loaded). */
    public static ObjectNode heartbeat(boolean ready, String readiness) {
        return NODES.objectNode().put("type", "heartbeat").put("ready", ready).put("readiness", readiness);
    }

    /** A sample the daemon hands to the placed method's input {@code input}. */
    public static Frame inputSample(String input, Sample sample) {
        Frame f = SampleCodec.sampleFrame(input, sample);
        ObjectNode h = f.header();
        h.remove("output");
        h.put("input", input);
        return f;
    }

    /** A sample the placed method published on its output {@code output}. */
    public static Frame outputSample(String output, Sample sample) {
        return SampleCodec.sampleFrame(output, sample);
    }

    /** The text of a field, or a {@code bad_value} error naming it. */
    public static String text(Frame frame, String field) throws FrameException {
        JsonNode n = frame.header().get(field);
        if (n == null || !n.isTextual() || n.textValue().isEmpty()) {
            throw FrameException.badValue("\"" + field + "\" must be a non-empty string");
        }
        return n.textValue();
    }

    private static String abbreviate(String s) {
        return s.length() <= 80 ? s : s.substring(0, 77) + "...";
    }
}
