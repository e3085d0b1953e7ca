package org.habla.drivers.pioneer;

/**
 * The client commands this driver sends, with their numbers, and the encoding of their arguments.
 *
 * <p>An integer argument travels as a type byte and two little-endian bytes: {@code 0x3B} and the value
 * when it is positive or zero, {@code 0x1B} and the <em>magnitude</em> when it is negative (never two's
 * complement). A command without an argument is the command byte alone.
 */
public enum ArcosCommand {
    /** First handshake step (before OPEN). */
    SYNC0(0),
    /** Second handshake step. */
    SYNC1(1),
    /** Third handshake step; the reply carries the robot's name, class and subclass. */
    SYNC2(2),
    /** Keep-alive: resets the robot's watchdog and does nothing else (same number as SYNC0). */
    PULSE(0),
    /** Starts the motor and sonar servers and the SIP stream (same number as SYNC1). */
    OPEN(1),
    /** Ends the session: motors and sonar off, the controller back to waiting (same number as SYNC2). */
    CLOSE(2),
    /** 1 enables the motors, 0 disables them. */
    ENABLE(4),
    /** Translational velocity set-point, mm/s, + forward. */
    VEL(11),
    /** Rotational velocity set-point, deg/s, + counter-clockwise. */
    RVEL(21),
    /** 1 turns every sonar on, 0 turns them off. */
    SONAR(28),
    /** Stops translation and rotation at the configured deceleration; motors stay enabled. */
    STOP(29),
    /** Emergency stop at maximum deceleration; motion commands are ignored until the robot has stopped. */
    E_STOP(55);

    /** Argument type byte: a positive (or zero) integer follows. */
    public static final int ARG_INT = 0x3B;
    /** Argument type byte: the magnitude of a negative integer follows. */
    public static final int ARG_NEG_INT = 0x1B;
    /** The largest magnitude an integer argument can carry. */
    public static final int MAX_ARG = 0xFFFF;

    private final int number;

    ArcosCommand(int number) {
        this.number = number;
    }

    /** The command number, the first data byte of the packet. */
    public int number() {
        return number;
    }

    /** The command without an argument. */
    public ArcosPacket packet() {
        return ArcosPacket.wrap(new byte[] {(byte) number});
    }

    /** The command with an integer argument in -65535..65535. */
    public ArcosPacket packet(int argument) {
        int magnitude = Math.abs(argument);
        if (magnitude > MAX_ARG) {
            throw new IllegalArgumentException(name() + " argument " + argument + " is outside -" + MAX_ARG + ".." + MAX_ARG);
        }
        return ArcosPacket.wrap(new byte[] {
            (byte) number, (byte) (argument < 0 ? ARG_NEG_INT : ARG_INT), (byte) magnitude, (byte) (magnitude >>> 8)});
    }
}
