package org.habla.recording;

import org.habla.sample.Sample;

/**
 * One record of a recording after its header. {@code t} is the engine clock's time (microseconds since the
 * epoch, scaled like the engine's clock) when HABLA saw the event; a sample also keeps its own source time.
 */
public sealed interface RecordedEvent {

    /** When HABLA saw it, in engine-clock microseconds. */
    long t();

    /** A reading decoded from an interface channel. */
    record Reading(long t, String iface, String channel, Sample sample) implements RecordedEvent {
    }

    /** A command the graph wrote ({@code sent}) or dropped on an interface channel. */
    record Command(long t, String iface, String channel, Sample sample, boolean sent) implements RecordedEvent {
    }

    /** A value a control client wrote to an exposed method's input. */
    record ControlWrite(long t, String socket, String input, Sample sample) implements RecordedEvent {
    }

    /** The last control client that wrote to a socket left (the motion watchdog stopped the robot). */
    record WriterLeft(long t, String socket) implements RecordedEvent {
    }

    /** An interface link went up or down. */
    record LinkChange(long t, String iface, boolean up) implements RecordedEvent {
    }

    /** A sample an exposed method emitted. */
    record Output(long t, String method, String output, Sample sample) implements RecordedEvent {
    }

    /**
     * Periodic work ran: {@code "watchdog"} or {@code "tick:METHOD"} (a method's tick, taken after the method
     * had handled {@code handled} input samples; -1 when not told), so a replay runs it between the same events.
     */
    /**
     * The {@code arrival}-th sample offered to a method's input never reached the method: a {@code latest} input
     * replaced it by a newer one, or a full queue dropped it.
     */
    record Skip(long t, String method, String input, long arrival) implements RecordedEvent {
    }

    record Tick(long t, String task, long handled) implements RecordedEvent {
    }

    /**
     * A command accepted or refused, or an authentication refused, on a control socket: the audit log's entry
     * ({@link org.habla.security.AuditEntry#json}). A replay does not act on it: it says who drove.
     */
    record Audit(long t, com.fasterxml.jackson.databind.node.ObjectNode entry) implements RecordedEvent {
    }

    /** The recorder had to drop events (its queue was full): {@code total} since the recording began. */
    record Dropped(long t, long total) implements RecordedEvent {
    }

    /** The recording was closed cleanly; a file killed mid-run has no end record. */
    record End(long t, long written, long dropped) implements RecordedEvent {
    }
}
