package org.habla.graph;

import org.habla.sample.Sample;

/**
 * Sees everything that crosses the graph's edges — readings from the hardware, commands to it,
 * values from control clients, link changes, the outputs of exposed methods, the samples a busy method skipped
 * and who drove the robot — for recording and audit. An observer only: nothing it returns changes what the
 * graph does (what a replay decides for the engine is {@link RecordedSkips}'s). Called on engine threads:
 * implementations must not block (hand off to a queue of their own).
 */
public interface GraphTap {

    /** A reading decoded from an interface channel. */
    void reading(String interfaceId, String channel, Sample sample);

    /** A command written (or dropped) on an interface channel. */
    void command(String interfaceId, String channel, Sample sample, boolean sent);

    /** A value a control client wrote to an exposed method's input. */
    void control(String socket, String input, Sample sample);

    /**
     * The last control client that wrote to an exposed method's socket left (the motion watchdog stops the
     * robot then), so a replay can leave at the same point.
     */
    default void writerLeft(String socket) {
    }

    /**
     * Periodic work ran: {@code "watchdog"} (the motion watchdog's check) or {@code "tick:METHOD"} (a method's
     * tick, as the method takes it, after it had handled {@code handled} input samples; -1 for the watchdog),
     * so a replay runs it between the same events.
     */
    default void periodic(String task, long micros, long handled) {
    }

    /**
     * A sample offered to a method's input never reached the method: a {@code latest} input replaced it by a newer
     * one before the method took it, or a full {@code queue} input dropped it. {@code arrival} is its place among
     * the samples offered to that input (1 for the first), so a replay can skip the same one ({@link RecordedSkips}):
     * which samples a busy method skipped is decided by timing, and the replay has none.
     */
    default void skipped(String methodId, String input, long arrival) {
    }

    /**
     * A command was accepted or refused, or an authentication refused, on a control socket (the audit log's
     * entry), so a recording shows who drove the robot.
     */
    default void audit(org.habla.security.AuditEntry entry) {
    }

    /** An interface link went up or down. */
    void link(String interfaceId, boolean up, long micros);

    /** A sample emitted by an exposed method. */
    void output(String methodId, String output, Sample sample);

    /** The tap that sees nothing. */
    GraphTap NONE = new GraphTap() {
        @Override
        public void reading(String interfaceId, String channel, Sample sample) {
        }

        @Override
        public void command(String interfaceId, String channel, Sample sample, boolean sent) {
        }

        @Override
        public void control(String socket, String input, Sample sample) {
        }

        @Override
        public void link(String interfaceId, boolean up, long micros) {
        }

        @Override
        public void output(String methodId, String output, Sample sample) {
        }
    };
}
