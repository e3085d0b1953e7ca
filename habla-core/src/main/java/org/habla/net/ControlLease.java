package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Who commands one actuating socket: at most one client at a time, its <em>commander</em>.
 *
 * <pre>
 *   free ──accepted write──▶ held by A ──A leaves / {"op":"release"}──▶ free      (the robot is stopped)
 *                              │  ▲
 *   B writes ──▶ error "busy"  │  └── A writes again (its silence starts over)
 *   B {"op":"take"} ───────────┴──▶ held by B      (A and every client are told; logged)
 *   A silent for the lapse time ──▶ the next client to write takes it, as if free (A is told)
 * </pre>
 *
 * The engine keeps one lease per actuating exposed method ({@link ControlPoint#lease}), shared by everything that
 * writes to it: the clients of its control socket and the bridges that carry it.
 *
 * <p>A write is checked and done under the lease's lock, so two clients that write at once cannot both command
 * the robot, and a write the engine refuses changes nothing: a client becomes commander only by a value the
 * engine took. The commander's leaving or releasing stops the robot (the engine's motion watchdog); a client
 * that never commanded leaves without effect. The lapse time is the motion watchdog's: a commander silent that
 * long has already had the robot stopped, so it no longer stands in anyone's way; with no watchdog (0) control
 * lapses only by leaving, releasing or being taken, or after the commander's own hold time
 * ({@link Client#holdMillis}: a bridge's) when it has one.
 */
public final class ControlLease {

    private static final Logger LOG = LoggerFactory.getLogger(ControlLease.class);

    /** A client as the lease sees it: a control socket's connection, or a bridge. */
    public interface Client {
        ClientId id();

        /**
         * How long this client keeps control while silent when that is shorter than the lease's lapse time, or
         * the lease has none: a commander that cannot leave (a bridge, whose actions come one by one from a
         * broker) still lets go. 0: the lease's lapse time alone.
         */
        default long holdMillis() {
            return 0;
        }
    }

    /** A write that the lease lets through; throws what the engine's write throws. */
    @FunctionalInterface
    public interface Write {
        void run() throws ControlPoint.Rejected;
    }

    private final String socket;
    private final long lapseMicros;
    private final LongSupplier clockMicros;
    private final Runnable commanderLeft;
    private final Consumer<Frame> everyone;
    private Client holder;
    private long sinceMicros;
    private long lastWriteMicros;

    /**
     * @param lapseMillis   silence after which the commander no longer holds control; 0 for never
     * @param commanderLeft what stops the robot when the commander leaves or releases control
     * @param everyone      hands a notice to every client of the socket
     */
    public ControlLease(String socket, long lapseMillis, LongSupplier clockMicros, Runnable commanderLeft,
            Consumer<Frame> everyone) {
        this.socket = socket;
        this.lapseMicros = lapseMillis * 1_000;
        this.clockMicros = clockMicros;
        this.commanderLeft = commanderLeft;
        this.everyone = everyone;
    }

    /** Does {@code write} for {@code client} unless another client commands the socket. */
    public synchronized void write(Client client, Write write) throws ControlPoint.Rejected {
        long now = clockMicros.getAsLong();
        if (holder != null && holder != client && !lapsed(now)) {
            throw new ControlPoint.Rejected("busy", "socket '" + socket + "' is commanded by " + holder.id()
                    + " since " + Instant.ofEpochSecond(0, sinceMicros * 1_000) + " (last write "
                    + (now - lastWriteMicros) / 1_000 + " ms ago); send {\"op\":\"take\"} to take control");
        }
        write.run();
        if (holder != client) {
            Client previous = holder;
            String why = previous == null ? "first write" : "the commander " + previous.id() + " was silent for "
                    + (now - lastWriteMicros) / 1_000 + " ms";
            change(client, now, why, previous);
        }
        lastWriteMicros = now;
    }

    /** Makes {@code client} the commander, whoever held control. */
    public synchronized void take(Client client) {
        if (holder == client) {
            return;
        }
        long now = clockMicros.getAsLong();
        Client previous = holder;
        String why = previous == null ? "taken" : "taken from " + previous.id() + ", commander since "
                + Instant.ofEpochSecond(0, sinceMicros * 1_000);
        change(client, now, why, previous);
        lastWriteMicros = now;
    }

    /** The commander gives control back; the robot is stopped. */
    public synchronized void release(Client client) throws ControlPoint.Rejected {
        if (holder != client) {
            throw new ControlPoint.Rejected("not_commander", holder == null
                    ? "nobody commands socket '" + socket + "'"
                    : "socket '" + socket + "' is commanded by " + holder.id() + ", not by this connection");
        }
        change(null, clockMicros.getAsLong(), "released by " + client.id(), null);
        commanderLeft.run();
    }

    /** A client disconnected: if it was the commander, control is free and the robot is stopped. */
    public synchronized void left(Client client) {
        if (holder == client) {
            change(null, clockMicros.getAsLong(), client.id() + " disconnected", null);
            commanderLeft.run();
        }
    }

    /** Who commands now: {@code holder} (null when free), {@code since}, and how long it has been silent. */
    public synchronized ObjectNode status() {
        long now = clockMicros.getAsLong();
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        if (holder == null || lapsed(now)) {
            n.putNull("holder");
            return n;
        }
        n.set("holder", holder.id().toJson());
        n.put("since", Instant.ofEpochSecond(0, sinceMicros * 1_000).toString());
        n.put("sinceT", sinceMicros);
        n.put("silentMs", (now - lastWriteMicros) / 1_000);
        return n;
    }

    private boolean lapsed(long now) {
        long limit = lapseMicros;
        long hold = holder == null ? 0 : holder.holdMillis() * 1_000;
        if (hold > 0 && (limit == 0 || hold < limit)) {
            limit = hold;
        }
        return limit > 0 && now - lastWriteMicros > limit;
    }

    private void change(Client to, long now, String why, Client previous) {
        holder = to;
        sinceMicros = now;
        ObjectNode line = JsonNodeFactory.instance.objectNode().put("type", "control");
        if (to == null) {
            line.putNull("holder");
        } else {
            line.set("holder", to.id().toJson());
            line.put("since", now);
        }
        line.put("why", why);
        Frame notice = Frame.of(line);
        if (previous != null) {
            LOG.info("socket '{}': {} commands now ({})", socket, to.id(), why);
        } else if (to == null) {
            LOG.info("socket '{}': nobody commands now ({})", socket, why);
        } else {
            LOG.debug("socket '{}': {} commands now ({})", socket, to.id(), why);
        }
        everyone.accept(notice);
    }
}
