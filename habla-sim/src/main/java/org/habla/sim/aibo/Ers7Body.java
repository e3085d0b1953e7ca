package org.habla.sim.aibo;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * The simulated ERS-7's body as its servers see it: the emergency stop, the walk the remote control
 * asked for, the head joints moving towards their targets, the touch sensors and the infrared readings
 * the world fills in. Thread-safe: the servers, the world's stepping and the ground-truth server all
 * use it.
 *
 * <p>Units follow Tekkotsu's World State: joint angles in radians, infrared in millimetres, buttons
 * as scaled pressures, accelerations in m/s².
 */
public final class Ers7Body {

    /** Walk speeds at fraction ±1: Tekkotsu's compiled WalkMC defaults (180 mm/s, 140 mm/s, 1.8 rad/s). */
    public static final double MAX_FORWARD_MPS = 0.18;
    public static final double MAX_REVERSE_MPS = 0.18;
    public static final double MAX_STRAFE_MPS = 0.14;
    public static final double MAX_ROTATE_RADPS = 1.8;
    /** The walk remote control's dead-man time-out: no command for this long and the walk stops. */
    public static final long WALK_TIMEOUT_MS = 3_000;

    /** Head joint limits (ERS-7 {@code outputRanges}), radians: tilt, pan, nod. */
    static final double[] HEAD_MIN_RAD = {Math.toRadians(-75), Math.toRadians(-88), Math.toRadians(-15)};
    static final double[] HEAD_MAX_RAD = {0, Math.toRadians(88), Math.toRadians(45)};
    /** Head joint speed limits ({@code motion.max_head_*_speed}), rad/s: tilt, pan, nod. */
    static final double[] HEAD_SPEED_RADPS = {3.185, 5.781, 5.781};

    /** A touch pressure while pressed, in the scaled units the World State reports (about 0..1). */
    static final float TOUCH_PRESSURE = 0.8f;

    /** The walk being carried out: forward and strafe (+ left) in m/s, rotation (+ counter-clockwise) in rad/s. */
    public record Walk(double forwardMps, double strafeMps, double rotateRadps) {
        public static final Walk STILL = new Walk(0, 0, 0);
    }

    /** The head joints in radians: tilt (+ up), pan (+ left), nod (+ up). */
    public record HeadPose(double tiltRad, double panRad, double nodRad) {
    }

    private final List<Consumer<Boolean>> eStopListeners = new CopyOnWriteArrayList<>();
    private boolean eStopped = true;
    private float forwardFraction;
    private float strafeFraction;
    private float rotateFraction;
    private long lastWalkCommandMs = Long.MIN_VALUE / 2;
    private long walkCommands;
    private final double[] headTarget = new double[3];
    private final double[] head = new double[3];
    private final float[] ir = {500f, 1500f, 900f};
    private final long[] pressedUntilMs = new long[Ers7Layout.NUM_BUTTONS];
    private double gaitPhase;

    /** True while the emergency stop is engaged: the Aibo boots that way and ignores motion until released. */
    public synchronized boolean eStopped() {
        return eStopped;
    }

    /** Engages or releases the emergency stop and tells the listeners when that changes it. */
    public void setEStop(boolean stopped) {
        boolean changed;
        synchronized (this) {
            changed = eStopped != stopped;
            eStopped = stopped;
        }
        if (changed) {
            eStopListeners.forEach(l -> l.accept(stopped));
        }
    }

    void onEStopChange(Consumer<Boolean> listener) {
        eStopListeners.add(listener);
    }

    void removeEStopListener(Consumer<Boolean> listener) {
        eStopListeners.remove(listener);
    }

    /** One command of the walk remote control ({@code f}, {@code s} or {@code r}) received at {@code nowMs}. */
    synchronized void walkCommand(char letter, float value, long nowMs) {
        float v = Float.isFinite(value) ? Math.max(-1f, Math.min(1f, value)) : 0f;
        switch (letter) {
            case 'f' -> forwardFraction = v;
            case 's' -> strafeFraction = v;
            case 'r' -> rotateFraction = v;
            default -> {
                return;
            }
        }
        lastWalkCommandMs = nowMs;
        walkCommands++;
    }

    /** The walk commands received since boot (whether the emergency stop let them move the body or not). */
    public synchronized long walkCommands() {
        return walkCommands;
    }

    /** The walk at {@code nowMs}: still while the emergency stop is on or the remote control has gone quiet. */
    public synchronized Walk walk(long nowMs) {
        if (eStopped || nowMs - lastWalkCommandMs > WALK_TIMEOUT_MS) {
            return Walk.STILL;
        }
        double forward = forwardFraction * (forwardFraction > 0 ? MAX_FORWARD_MPS : MAX_REVERSE_MPS);
        return new Walk(forward, strafeFraction * MAX_STRAFE_MPS, rotateFraction * MAX_ROTATE_RADPS);
    }

    /**
     * One command of the head remote control: {@code t}, {@code p} or {@code r} (nod on the ERS-7) with
     * a value v mapped to the angle |v| × (v &gt; 0 ? joint max : joint min), as Tekkotsu does.
     */
    synchronized void headCommand(char letter, float value) {
        int joint = switch (letter) {
            case 't' -> 0;
            case 'p' -> 1;
            case 'r' -> 2;
            default -> -1;
        };
        if (joint < 0 || !Float.isFinite(value)) {
            return;
        }
        double v = Math.max(-1, Math.min(1, value));
        headTarget[joint] = Math.abs(v) * (v > 0 ? HEAD_MAX_RAD[joint] : HEAD_MIN_RAD[joint]);
    }

    public synchronized HeadPose head() {
        return new HeadPose(head[0], head[1], head[2]);
    }

    /** Presses a touch sensor ({@link Ers7Layout#HEAD_BUTTON}, a back segment) until {@code untilMs}. */
    public synchronized void press(int button, long untilMs) {
        pressedUntilMs[button] = Math.max(pressedUntilMs[button], untilMs);
    }

    /** The infrared distances in metres, [near, far, chest], as the world measured them. */
    public synchronized void setInfrared(double nearM, double farM, double chestM) {
        ir[0] = (float) (nearM * 1000);
        ir[1] = (float) (farM * 1000);
        ir[2] = (float) (chestM * 1000);
    }

    /**
     * Advances the joints by {@code dtS} seconds: the head moves towards its target no faster than its
     * speed limits, the legs swing with the walk. Nothing moves while the emergency stop is engaged.
     */
    public synchronized void step(double dtS, long nowMs) {
        if (eStopped) {
            return;
        }
        for (int j = 0; j < 3; j++) {
            double max = HEAD_SPEED_RADPS[j] * dtS;
            head[j] += Math.max(-max, Math.min(max, headTarget[j] - head[j]));
        }
        Walk w = walk(nowMs);
        double effort = Math.abs(w.forwardMps()) / MAX_FORWARD_MPS + Math.abs(w.strafeMps()) / MAX_STRAFE_MPS
                + Math.abs(w.rotateRadps()) / MAX_ROTATE_RADPS;
        if (effort > 0) {
            gaitPhase = (gaitPhase + dtS * 2 * Math.PI * 1.5) % (2 * Math.PI);
        }
    }

    /** What the World State Serializer sends at {@code nowMs}. */
    synchronized Ers7Layout.Snapshot snapshot(long nowMs) {
        boolean walking = !walk(nowMs).equals(Walk.STILL);
        float[] buttons = new float[Ers7Layout.NUM_BUTTONS];
        for (int b = 0; b < buttons.length; b++) {
            buttons[b] = pressedUntilMs[b] > nowMs ? TOUCH_PRESSURE : 0f;
        }
        return Ers7Layout.snapshot(head.clone(), walking ? gaitPhase : Double.NaN, ir.clone(), buttons,
                nowMs / 1000.0);
    }
}
