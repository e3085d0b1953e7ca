// Over 300 lines, on purpose: every request of habla-control/1, the auth line among them, is answered here from the
// same point, lease and security, as the picture below lists them; the hello is ControlHello's, values SampleCodec's.
package org.habla.net;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.habla.security.AuditEntry;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Role;

/**
 * The control protocol {@code habla-control/1} of one connection: the hello line, and the answer to each
 * request a client sends. Knows nothing of sockets: it reads frames and hands replies to a {@link Replies}.
 *
 * <pre>
 *   client                                      server
 *   {"op":"write","input":"action","value":..}  -&gt; ok (if "id") | error
 *   {"value":..}                                -&gt; the same, to the only control input
 *   {"op":"latest"}                             -&gt; one sample line per output that has one, then ok (if "id")
 *   {"op":"rate","maxHz":5}                     -&gt; ok (if "id"); samples thinned to 5 a second per output
 *   {"op":"ping"}                               -&gt; {"type":"pong"} (with the "id", which acknowledges it)
 *   {"op":"take"}                               -&gt; ok (if "id"); this client commands the socket now
 *   {"op":"release"}                            -&gt; ok (if "id") | error not_commander; the robot is stopped
 *   {"op":"auth","client":NAME,"token":TOKEN}   -&gt; the full hello | error auth_failed / auth_throttled / forbidden /
 *                                                  too_many_clients, then closed | error already_authenticated
 * </pre>
 *
 * On an actuating socket a write goes through the socket's {@link ControlLease}: one commander at a time.
 *
 * <p>Where the port requires authentication ({@link PortAccess}), the first hello says only {@code "auth":
 * "required"}; the client's first request must be its auth line, which earns it the full hello, then its samples.
 * Anything else first — another request, a line the framing refuses, a block — gets {@code auth_required} and the
 * connection closes; no block is read before authentication. Writing, taking and releasing need
 * the {@code command} role on the socket, reading needs {@code read}. Every write, take and release, accepted or
 * not, and every refused authentication goes to the port's audit log.
 */
final class ControlProtocol {

    static final String PROTOCOL = "habla-control/1";

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    /** Where the protocol's answers go, and the per-connection settings it changes; the client it serves. */
    interface Replies extends ControlLease.Client {
        void reply(Frame frame) throws InterruptedException;

        void rate(double maxHz);

        /** Who the connection has proved to be; null until it has (never null on an open port). */
        PortAccess.Admitted admitted();

        /**
         * The connection has proved who it is: once the port has a client's place for it, it is sent {@code hello}
         * and from then on gets samples and notices (never before the hello) and may use its role.
         *
         * @param requestId the auth line's {@code "id"}, for the error line of a refusal
         * @return whether it is a client; if not, it has been told why and closed
         */
        boolean admit(PortAccess.Admitted admitted, JsonNode requestId, Frame hello) throws InterruptedException;

        /**
         * Sends {@code error} (after {@link PortAccess#FAILURE_DELAY_MS} when {@code delay}) and closes the
         * connection.
         */
        void refuse(Frame error, boolean delay) throws InterruptedException;
    }

    private final ControlPoint point;
    private final Limits limits;
    private final ControlLease lease;
    private final PortSecurity security;

    /** @param lease who commands the socket; null when its values reach no actuator */
    ControlProtocol(ControlPoint point, Limits limits, ControlLease lease) {
        this(point, limits, lease, PortSecurity.open(point.name()));
    }

    /**
     * @param lease    who commands the socket; null when its values reach no actuator
     * @param security who may use the socket, and where its commands are audited
     */
    ControlProtocol(ControlPoint point, Limits limits, ControlLease lease, PortSecurity security) {
        this.point = point;
        this.limits = limits;
        this.lease = lease;
        this.security = security;
    }

    /** Who a new connection is before it says: anonymous with every role on an open port, nobody otherwise. */
    PortAccess.Admitted initialAccess() {
        return security.access().required() ? null : security.access().anonymous();
    }

    /**
     * The line a client gets on connect: the full hello on an open port; where authentication is required, only
     * the protocol, the socket's name and {@code "auth":"required"}.
     */
    Frame hello() {
        return security.access().required() ? ControlHello.authRequired(point, limits)
                : ControlHello.full(point, limits, lease, null);
    }

    /** Answers one request. */
    void handle(Frame request, Replies replies) throws InterruptedException {
        ObjectNode h = request.header();
        JsonNode id = h.get("id");
        String op = h.has("op") ? h.get("op").asText() : h.has("value") || request.hasBody() ? "write" : "";
        if (op.equals("auth")) {
            auth(h, id, replies);
            return;
        }
        PortAccess.Admitted who = replies.admitted();
        if (who == null) {
            Frame refusal = authRequired(null, id);
            if (commands(op)) {
                audit(replies, op, request, "auth_required: " + refusal.header().path("message").asText());
            }
            replies.refuse(refusal, false);
            return;
        }
        if (commands(op) && !who.role().covers(Role.COMMAND)) {
            String why = "client '" + who.principal().name() + "' may only read socket '" + point.name()
                    + "' (role read); " + op + " needs the command role";
            audit(replies, op, request, "forbidden: " + why);
            replies.reply(error("forbidden", why, id));
            return;
        }
        try {
            switch (op) {
                case "write" -> audited(replies, op, request, () -> write(request, replies));
                case "latest" -> latest(replies);
                case "rate" -> rate(h, replies);
                case "take" -> audited(replies, op, request, () -> commanded().take(replies));
                case "release" -> audited(replies, op, request, () -> commanded().release(replies));
                case "ping" -> {
                    ObjectNode pong = NODES.objectNode().put("type", "pong");
                    if (id != null) {
                        pong.set("id", id);
                    }
                    replies.reply(Frame.of(pong));
                    return;
                }
                default -> throw FrameException.recoverable("unknown_op", (op.isEmpty()
                        ? "a request needs \"op\" (or a \"value\" to write)"
                        : "unknown op '" + op + "'") + "; ops are write, latest, rate, ping, take, release, auth");
            }
            if (id != null) {
                ObjectNode ok = NODES.objectNode().put("type", "ok");
                ok.set("id", id);
                replies.reply(Frame.of(ok));
            }
        } catch (FrameException e) {
            replies.reply(error(e.code(), e.getMessage(), id));
        } catch (ControlPoint.Rejected e) {
            String code = e.code() == null || e.code().isBlank() ? "rejected" : e.code();
            replies.reply(error(code, e.getMessage(), id));
        }
    }

    /**
     * The error line of a connection that sent something other than an auth line before authenticating: a request,
     * or a line the framing refused ({@code problem}, null for a request).
     */
    Frame authRequired(String problem, JsonNode id) {
        return error("auth_required", "socket '" + point.name() + "' requires authentication before anything else: "
                + "send {\"op\":\"auth\",\"client\":NAME,\"token\":TOKEN} first"
                + (problem == null ? "" : " (the line was refused: " + problem + ")"), id);
    }

    /** Whether {@code op} drives the robot (needs the command role, and is audited). */
    private static boolean commands(String op) {
        return op.equals("write") || op.equals("take") || op.equals("release");
    }

    /** A command that may be refused. */
    @FunctionalInterface
    private interface Command {
        void run() throws FrameException, ControlPoint.Rejected;
    }

    /** Does {@code command} and audits it, accepted or refused with its error code. */
    private void audited(Replies replies, String op, Frame request, Command command)
            throws FrameException, ControlPoint.Rejected {
        try {
            command.run();
        } catch (FrameException e) {
            audit(replies, op, request, e.code() + ": " + e.getMessage());
            throw e;
        } catch (ControlPoint.Rejected e) {
            audit(replies, op, request, (e.code() == null || e.code().isBlank() ? "rejected" : e.code()) + ": "
                    + e.getMessage());
            throw e;
        }
        audit(replies, op, request, null);
    }

    /** One audit entry: accepted when {@code why} is null. */
    private void audit(Replies replies, String op, Frame request, String why) {
        ClientId id = replies.id();
        JsonNode value = null;
        String input = null;
        if (op.equals("write")) {
            JsonNode named = request.header().get("input");
            List<Input<?>> inputs = point.controlInputs();
            input = named != null ? named.asText() : inputs.size() == 1 ? inputs.get(0).name() : null;
            value = request.hasBody()
                    ? NODES.objectNode().put("bytes", request.header().path("bytes").asLong())
                    : request.header().get("value");
        }
        security.audit().add(new AuditEntry(Instant.now(), id.client(), id.address(), point.name(), op,
                input, value, why == null, why));
    }

    private void auth(ObjectNode h, JsonNode id, Replies replies) throws InterruptedException {
        if (replies.admitted() != null && security.access().required()) {
            replies.reply(error("already_authenticated", "this connection is already client '"
                    + replies.admitted().principal().name() + "'", id));
            return;
        }
        if (!security.access().required()) {
            replies.reply(ControlHello.full(point, limits, lease, null)); // an open port: a client configured with a token still gets on
            return;
        }
        ClientId who = replies.id();
        switch (security.access().authenticate(h, who.host())) {
            case PortAccess.Admitted a -> {
                replies.admit(a, id, ControlHello.full(point, limits, lease, a));
            }
            case PortAccess.Refused r -> {
                security.audit().add(new AuditEntry(Instant.now(), r.client(), who.address(), point.name(),
                        "auth", null, null, false, r.code() + ": " + r.message()));
                replies.refuse(error(r.code(), r.message(), id), r.delayed());
            }
        }
    }

    private void write(Frame request, Replies replies) throws FrameException, ControlPoint.Rejected {
        List<Input<?>> inputs = point.controlInputs();
        if (inputs.isEmpty()) {
            throw FrameException.recoverable("read_only", "socket '" + point.name() + "' takes no values");
        }
        JsonNode named = request.header().get("input");
        Input<?> input;
        if (named == null) {
            if (inputs.size() != 1) {
                throw FrameException.recoverable("unknown_input", "name the \"input\": one of " + names(inputs));
            }
            input = inputs.get(0);
        } else {
            input = inputs.stream().filter(i -> i.name().equals(named.asText())).findFirst()
                    .orElseThrow(() -> FrameException.recoverable("unknown_input",
                            "no input " + named + "; inputs are " + names(inputs)));
        }
        Payload value = SampleCodec.value(request, input.kind());
        if (lease == null) {
            point.write(input, value);
        } else {
            lease.write(replies, () -> point.write(input, value));
        }
    }

    /** The client has gone: if it commanded the socket, control is free and the robot is stopped. */
    void left(ControlLease.Client client) {
        if (lease != null) {
            lease.left(client);
        }
    }

    private ControlLease commanded() throws FrameException {
        if (lease == null) {
            throw FrameException.recoverable("no_control", "socket '" + point.name()
                    + "' moves nothing: there is no control to take or release");
        }
        return lease;
    }

    private void latest(Replies replies) throws InterruptedException {
        Map<String, Sample> latest = point.latest();
        for (Output<?> o : point.outputs()) {
            Sample s = latest.get(o.name());
            if (s != null) {
                replies.reply(SampleCodec.sampleFrame(o.name(), s));
            }
        }
    }

    private static void rate(ObjectNode h, Replies replies) throws FrameException {
        JsonNode maxHz = h.get("maxHz");
        if (maxHz == null || !maxHz.isNumber() || !(maxHz.doubleValue() >= 0) || maxHz.doubleValue() > 1e6) {
            throw FrameException.badValue("\"maxHz\" must be a number in [0, 1000000] (0: no limit), was " + maxHz);
        }
        replies.rate(maxHz.doubleValue());
    }

    /** An error line. */
    static Frame error(String code, String message, JsonNode id) {
        ObjectNode e = NODES.objectNode().put("type", "error").put("code", code).put("message", message);
        if (id != null) {
            e.set("id", id);
        }
        return Frame.of(e);
    }

    private static List<String> names(List<Input<?>> inputs) {
        return inputs.stream().map(Input::name).toList();
    }
}
