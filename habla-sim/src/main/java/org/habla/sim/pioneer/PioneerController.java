// Over 300 lines, on purpose: the ARCOS state machine shares the controller's state under one lock.
package org.habla.sim.pioneer;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import java.util.Random;
import java.util.function.Consumer;
import org.habla.sim.world.Body;
import org.habla.sim.world.Pose2;
import org.habla.sim.world.Scene;
import org.habla.sim.world.SimClock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated Pioneer's controller board: the ARCOS state machine behind the socket. It answers the SYNC
 * handshake, starts its servers on OPEN, keeps the motors disabled until ENABLE 1, turns VEL/RVEL/VEL2/STOP/E_STOP
 * into the body's set-points, fires its sonar ring, and every 100 ms of sim time sends a SIP with the odometry
 * (15-bit positions that roll over), wheel speeds, battery, stall and bumper bits and the sonar readings fired
 * since the last SIP. If no packet arrives for 2 s the watchdog stops the robot; the next packet resumes the last
 * set-points. CLOSE stops the motors and sonar and waits for a new handshake. The speed set-points are the
 * controller's memory, not the session's: only VEL, RVEL, VEL2, STOP and E_STOP change them, so after CLOSE and a
 * new handshake the robot stands only while its motors are disabled, and ENABLE 1 drives the old set-points again
 * unless a STOP came first — the firmware's "resume the last set-points", which a client must not rely on being
 * forgotten. A robot put elsewhere by a reset
 * keeps its odometry, as a robot carried by hand does. Like a real robot on a serial bridge it does not notice a
 * client that just vanishes: it stays open (the watchdog stops it), and a new client finds it streaming SIPs and
 * must CLOSE it first.
 *
 * <p>Packets arrive on the connection's reader thread, steps on the sim clock's thread; both lock this object.
 */
final class PioneerController implements SimClock.Stepper {

    private static final Logger LOG = LoggerFactory.getLogger(PioneerController.class);

    /** The name the robot gives in its SYNC2 reply. */
    static final String ROBOT_NAME = "HABLA-sim";

    private enum Phase { WAITING, SYNCED, OPEN }

    private final Scene scene;
    private final SonarModel sonar;
    private final Body body;
    private Consumer<byte[]> link = wire -> { };
    private Phase phase = Phase.WAITING;
    private boolean motorsEnabled;
    private boolean sonarOn;
    private double vMps;
    private double wRadps;
    private boolean eStopped;
    private boolean watchdogTripped;
    private double lastPacketS;
    private double nextSipS;
    private double nextFireS;
    private int frontNext;
    private int rearNext;
    private final Map<Integer, Integer> fired = new LinkedHashMap<>();
    private Pose2 odomOrigin = Pose2.ORIGIN;
    private Pose2 lastPose;
    private long packets;
    private long ignored;
    private long sips;

    PioneerController(Scene scene, Random random, double sonarNoiseM) {
        this.scene = scene;
        this.body = scene.body();
        this.sonar = new SonarModel(scene.world(), random, sonarNoiseM);
    }

    /** Directs what the robot sends to a new client's connection. */
    synchronized void attach(Consumer<byte[]> wireOut) {
        link = wireOut;
    }

    /** Forgets a client that left, if it is still the current one. */
    synchronized void detach(Consumer<byte[]> wireOut) {
        if (link == wireOut) {
            link = wire -> { };
        }
    }

    /** Handles one good packet from the client (command byte first). */
    synchronized void handle(byte[] data) {
        packets++;
        double now = scene.nowS();
        int cmd = data[0] & 0xFF;
        if (phase != Phase.OPEN) {
            handshake(cmd);
            return;
        }
        lastPacketS = now;
        if (watchdogTripped) {
            watchdogTripped = false;
            LOG.info("packets again after the watchdog stop: resuming the last set-points");
        }
        OptionalInt arg = ArcosArgs.intArg(data);
        switch (cmd) {
            case 0 -> { } // PULSE
            case 1 -> { } // OPEN again: already open
            case 2 -> close();
            case 4 -> motorsEnabled = arg.orElse(0) != 0; // ENABLE
            case 7 -> odomOrigin = body.pose(); // SETO
            case 11 -> { // VEL, mm/s
                if (arg.isPresent() && motionAllowed()) {
                    vMps = arg.getAsInt() / 1000.0;
                }
            }
            case 21 -> { // RVEL, deg/s
                if (arg.isPresent() && motionAllowed()) {
                    wRadps = Math.toRadians(arg.getAsInt());
                }
            }
            case 32 -> { // VEL2: high byte left, low byte right, each signed × 20 mm/s
                if (arg.isPresent() && motionAllowed()) {
                    short packed = (short) arg.getAsInt();
                    double left = (byte) (packed >> 8) * P2dx.VEL2_DIVISOR / 1000.0;
                    double right = (byte) packed * P2dx.VEL2_DIVISOR / 1000.0;
                    vMps = (left + right) / 2;
                    wRadps = (right - left) * 1000.0 / 2 * P2dx.DIFF_CONV;
                }
            }
            case 28 -> sonarOn = arg.orElse(1) != 0; // SONAR
            case 29 -> { // STOP
                vMps = 0;
                wRadps = 0;
            }
            case 55 -> { // E_STOP
                vMps = 0;
                wRadps = 0;
                eStopped = true;
                body.halt();
            }
            default -> {
                ignored++;
                LOG.debug("ignoring ARCOS command {} ({} ignored so far)", cmd, ignored);
            }
        }
    }

    private boolean motionAllowed() {
        return motorsEnabled && !eStopped;
    }

    private void handshake(int cmd) {
        switch (cmd) {
            case 0 -> send(new byte[] {0});
            case 1 -> {
                if (phase == Phase.SYNCED) {
                    open();
                } else {
                    send(new byte[] {1});
                }
            }
            case 2 -> {
                byte[] name = (ROBOT_NAME + "\0" + P2dx.ROBOT_CLASS + "\0" + P2dx.SUBCLASS + "\0")
                        .getBytes(StandardCharsets.ISO_8859_1);
                byte[] reply = new byte[name.length + 1];
                reply[0] = 2;
                System.arraycopy(name, 0, reply, 1, name.length);
                send(reply);
                phase = Phase.SYNCED;
            }
            default -> ignored++;
        }
    }

    private void open() {
        double now = scene.nowS();
        phase = Phase.OPEN;
        motorsEnabled = false; // on every new connection; the set-points stay
        sonarOn = true;
        eStopped = false;
        watchdogTripped = false;
        lastPacketS = now;
        nextSipS = now;
        nextFireS = now;
        fired.clear();
        odomOrigin = body.pose();
        LOG.info("ARCOS session open");
    }

    private void close() {
        phase = Phase.WAITING;
        motorsEnabled = false;
        sonarOn = false;
        body.command(0, 0, 0);
        LOG.info("ARCOS session closed by the client");
    }

    @Override
    public synchronized void step(double nowS, double dtS) {
        followCarrying(dtS);
        if (phase != Phase.OPEN) {
            body.command(0, 0, 0);
            return;
        }
        if (!watchdogTripped && nowS - lastPacketS > P2dx.WATCHDOG_S) {
            watchdogTripped = true;
            LOG.info("no packet for {} s: the watchdog stops the robot", P2dx.WATCHDOG_S);
        }
        if (eStopped && body.forwardMps() == 0 && body.turnRadps() == 0) {
            eStopped = false;
        }
        boolean drive = motorsEnabled && !watchdogTripped && !eStopped;
        body.command(drive ? vMps : 0, 0, drive ? wRadps : 0);
        if (!sonarOn) {
            nextFireS = nowS + dtS; // once switched on, the ring starts firing at its own pace
        } else if (nowS + 1e-9 >= nextFireS) {
            nextFireS += P2dx.SONAR_FIRE_PERIOD_S;
            fire(frontNext);
            fire(8 + rearNext);
            frontNext = (frontNext + 1) % 8;
            rearNext = (rearNext + 1) % 8;
        }
        if (nowS + 1e-9 >= nextSipS) {
            nextSipS += P2dx.SIP_PERIOD_S;
            send(SipEncoder.encode(sipFields()));
            sips++;
        }
    }

    private void fire(int index) {
        double m = sonar.read(scene.target(), body.pose(), P2dx.SONARS.get(index));
        fired.put(index, (int) Math.round(m * 1000 / P2dx.RANGE_CONV_MM));
    }

    private SipEncoder.Fields sipFields() {
        Pose2 odom = odometry();
        double v = body.forwardMps();
        double w = body.turnRadps();
        double halfDiffMmps = w / P2dx.DIFF_CONV;
        int left = (int) Math.round(v * 1000 - halfDiffMmps);
        int right = (int) Math.round(v * 1000 + halfDiffMmps);
        int th = (int) Math.round(odom.thetaRad() / P2dx.ANGLE_CONV_RAD);
        if (th >= 2048) {
            th -= 4096;
        }
        List<SipEncoder.Reading> readings = new ArrayList<>();
        fired.forEach((index, units) -> readings.add(new SipEncoder.Reading(index, units)));
        fired.clear();
        int flags = (motorsEnabled ? 0x01 : 0) | (sonarOn ? 0x1E : 0);
        return new SipEncoder.Fields(v != 0 || w != 0,
                (int) Math.round(odom.xM() * 1000 / P2dx.DIST_CONV_MM),
                (int) Math.round(odom.yM() * 1000 / P2dx.DIST_CONV_MM),
                th, left, right, P2dx.BATTERY_DV, stallAndBumpers(), flags, readings,
                (int) Math.round(Math.toDegrees(w) * 10));
    }

    /**
     * Keeps the odometry still when the robot is carried (put somewhere by a reset): its wheels did not turn. A
     * pose change no wheel could make in one step moves the odometry origin with the robot instead.
     */
    private void followCarrying(double dtS) {
        Pose2 now = body.pose();
        Pose2 before = lastPose;
        lastPose = now;
        if (before == null) {
            return;
        }
        double reach = 2 * P2dx.MAX_VEL_MPS * dtS + 1e-3;
        double turn = 2 * P2dx.MAX_ROT_VEL_RADPS * dtS + 1e-3;
        if (before.distanceTo(now.xM(), now.yM()) <= reach
                && Math.abs(Pose2.normalize(now.thetaRad() - before.thetaRad())) <= turn) {
            return;
        }
        Pose2 odom = relative(odomOrigin, before);
        double theta = now.thetaRad() - odom.thetaRad();
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        odomOrigin = new Pose2(now.xM() - (odom.xM() * c - odom.yM() * s), now.yM() - (odom.xM() * s + odom.yM() * c),
                theta);
        LOG.debug("the robot was carried to {}: odometry unchanged", now);
    }

    /** Where the robot thinks it is: its pose relative to where the session opened or SETO was sent. */
    private Pose2 odometry() {
        return relative(odomOrigin, body.pose());
    }

    /** {@code p} in the frame of {@code origin}. */
    private static Pose2 relative(Pose2 origin, Pose2 p) {
        double dx = p.xM() - origin.xM();
        double dy = p.yM() - origin.yM();
        double c = Math.cos(-origin.thetaRad());
        double s = Math.sin(-origin.thetaRad());
        return new Pose2(dx * c - dy * s, dx * s + dy * c, p.thetaRad() - origin.thetaRad());
    }

    /** Stall bits 0 and 8 together; a front (bits 9–13) or rear (bits 1–5) bumper where the body touches. */
    private int stallAndBumpers() {
        int bits = body.stalled() ? 0x0101 : 0;
        double b = body.contactBearingRad();
        if (!Double.isNaN(b)) {
            if (Math.abs(b) <= Math.PI / 2) {
                // Front bumpers 0..4 from the left side round to the right.
                int i = (int) Math.min(P2dx.FRONT_BUMPERS - 1, Math.floor((Math.PI / 2 - b) / (Math.PI / P2dx.FRONT_BUMPERS)));
                bits |= 1 << (9 + i);
            } else {
                // Rear bumpers 0..4 from the right side round to the left.
                double fromRight = Pose2.normalize(-Math.PI / 2 - b);
                fromRight = fromRight < 0 ? fromRight + 2 * Math.PI : fromRight;
                int i = (int) Math.min(P2dx.REAR_BUMPERS - 1, Math.floor(fromRight / (Math.PI / P2dx.REAR_BUMPERS)));
                bits |= 1 << (1 + i);
            }
        }
        return bits;
    }

    private void send(byte[] data) {
        link.accept(ArcosFrames.frame(data));
    }

    /** Packets received, ignored and SIPs sent, for the log. */
    synchronized String counters() {
        return packets + " packets (" + ignored + " ignored), " + sips + " SIPs";
    }
}
