package org.habla.config;

/**
 * The motion watchdog.
 *
 * @param watchdogMs the robot is stopped when no control client has written a value for this long, or at
 *                   once when the last control client of a method that takes values disconnects; 0 turns
 *                   the silence check off (the disconnect check stays)
 */
public record Safety(long watchdogMs) {

    public static final Safety DEFAULTS = new Safety(1_000);
}
