package org.habla.drivers.pioneer;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Optional;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.VectorValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One ARCOS session with a Pioneer, from SYNC0 to CLOSE.
 *
 * <p>Handshake: SYNC0, SYNC1, SYNC2, each sent only after the robot echoed the one before; the SYNC2
 * reply names the robot. A robot that answers with SIPs still has a session open from an earlier client:
 * it gets a CLOSE and the handshake starts again. Then OPEN, STOP, PULSE, ENABLE 1 (if {@code enableMotors})
 * and SONAR 1. The STOP comes before anything else of the new session: the controller keeps its last speed
 * set-points through a watchdog stop and resumes them on the next packet it gets, and nothing says a new session
 * clears them, so a robot left driving by a lost connection would otherwise drive on once its motors are
 * enabled again.
 *
 * <p>Stopping uses STOP (#29) rather than VEL 0 + RVEL 0: one packet that zeroes translation and rotation
 * together, also ends a MOVE, HEAD or VEL2 in progress, and keeps the motors enabled. It decelerates at
 * the configured rate. E_STOP (#55) is deliberately not used: it brakes at full deceleration and makes the
 * robot ignore motion commands until it has stopped, which is for emergencies, not for a quiet controller.
 *
 * <p>Threading: the decoder and the SIP translator belong to the reader; the write side only encodes.
 */
final class ArcosSession implements LinkSession {

    private static final Logger LOG = LoggerFactory.getLogger(ArcosSession.class);

    /** Full SYNC0..SYNC2 attempts before the handshake gives up (the engine then reconnects). */
    static final int HANDSHAKE_ATTEMPTS = 5;
    /** Packets to read while waiting for one SYNC reply before sending the SYNC again. */
    static final int PACKETS_PER_REPLY = 30;

    private final PioneerParams params;
    private final ArcosPacketDecoder decoder = new ArcosPacketDecoder();
    private final ArrayDeque<ArcosPacket> ready = new ArrayDeque<>();
    private final byte[] readBuffer = new byte[512];
    private final SipTranslator translator;
    private long ignoredPackets;

    ArcosSession(PioneerParams params) {
        this.params = params;
        this.translator = new SipTranslator(params);
    }

    @Override
    public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
        boolean closedStale = false;
        for (int attempt = 1; attempt <= HANDSHAKE_ATTEMPTS; attempt++) {
            SyncResult result = sync(in, out, sink, closedStale);
            if (result == SyncResult.DONE) {
                send(out, ArcosCommand.OPEN.packet());
                send(out, ArcosCommand.STOP.packet());
                send(out, ArcosCommand.PULSE.packet());
                if (params.enableMotors()) {
                    send(out, ArcosCommand.ENABLE.packet(1));
                }
                send(out, ArcosCommand.SONAR.packet(1));
                out.flush();
                return;
            }
            if (result == SyncResult.ROBOT_ALREADY_OPEN) {
                LOG.info("robot answered SYNC0 with SIPs (a session is still open): sending CLOSE and syncing again");
                send(out, ArcosCommand.CLOSE.packet());
                out.flush();
                closedStale = true;
            }
        }
        throw new IOException("ARCOS handshake failed after " + HANDSHAKE_ATTEMPTS + " attempts");
    }

    private enum SyncResult { DONE, ROBOT_ALREADY_OPEN, RESTART }

    private SyncResult sync(InputStream in, OutputStream out, ReadingSink sink, boolean closedStale) throws IOException {
        ArcosCommand[] steps = {ArcosCommand.SYNC0, ArcosCommand.SYNC1, ArcosCommand.SYNC2};
        for (ArcosCommand step : steps) {
            send(out, step.packet());
            out.flush();
            ArcosPacket reply = awaitSyncReply(in, sink, step, closedStale);
            if (reply == null) {
                return SyncResult.RESTART;
            }
            if (StandardSip.isSip(reply.type())) {
                return SyncResult.ROBOT_ALREADY_OPEN;
            }
            if (reply.type() != step.number()) {
                LOG.debug("SYNC{} answered out of order with type {}: restarting at SYNC0", step.number(), reply.type());
                return SyncResult.RESTART;
            }
            if (step == ArcosCommand.SYNC2) {
                RobotIdentity id = RobotIdentity.fromSync2(reply);
                translator.identity(id);
                ObjectNode info = JsonNodeFactory.instance.objectNode()
                        .put("protocol", "ARCOS")
                        .put("name", id.name())
                        .put("class", id.robotClass())
                        .put("subclass", id.subclass());
                sink.robotInfo(info);
                LOG.info("ARCOS robot '{}' ({} {})", id.name(), id.robotClass(), id.subclass());
            }
        }
        return SyncResult.DONE;
    }

    /**
     * The robot's answer to a SYNC: a SYNC echo or a SIP, or null after {@value #PACKETS_PER_REPLY} other
     * packets. SIPs left in the pipe from a session just closed are skipped.
     */
    private ArcosPacket awaitSyncReply(InputStream in, ReadingSink sink, ArcosCommand step, boolean closedStale)
            throws IOException {
        for (int i = 0; i < PACKETS_PER_REPLY; i++) {
            ArcosPacket p = nextPacket(in, sink);
            boolean sip = StandardSip.isSip(p.type());
            if (p.type() <= ArcosCommand.SYNC2.number() || (sip && !closedStale)) {
                return p;
            }
            LOG.debug("ignoring packet type 0x{} while waiting for the SYNC{} reply", Integer.toHexString(p.type()),
                    step.number());
        }
        return null;
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        ArcosPacket p = nextPacket(in, sink);
        if (StandardSip.isSip(p.type())) {
            StandardSip sip;
            try {
                sip = StandardSip.parse(p);
            } catch (IllegalArgumentException e) {
                sink.malformed("SIP: " + e.getMessage());
                return;
            }
            translator.translate(sip, sink);
        } else {
            ignoredPackets++;
            translator.ignoredPackets(ignoredPackets);
            LOG.debug("ignoring ARCOS packet type 0x{} ({} so far)", Integer.toHexString(p.type()), ignoredPackets);
        }
    }

    /** The next good packet, reading the socket only when none is waiting. */
    private ArcosPacket nextPacket(InputStream in, ReadingSink sink) throws IOException {
        ArcosPacketDecoder.Listener listener = new ArcosPacketDecoder.Listener() {
            @Override
            public void packet(ArcosPacket packet) {
                ready.add(packet);
            }

            @Override
            public void malformed(String what) {
                sink.malformed(what);
            }
        };
        while (ready.isEmpty()) {
            int n = in.read(readBuffer);
            if (n < 0) {
                throw new EOFException("the robot closed the ARCOS connection");
            }
            decoder.push(readBuffer, 0, n, listener);
        }
        return ready.poll();
    }

    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        switch (channel) {
            case PioneerChannels.MOTION -> writeMotion(command, out);
            case PioneerChannels.SONAR_POWER -> writeSonarPower(command, out);
            default -> throw new IOException("the ARCOS connection carries no command channel '" + channel + "'");
        }
    }

    /**
     * VEL then RVEL, clamped to the robot's limits. A value that is not two finite numbers is refused with a
     * warning and the robot is stopped instead: a controller that sends nonsense should not keep it driving.
     */
    private void writeMotion(Payload command, OutputStream out) throws IOException {
        if (!(command instanceof VectorValue v) || v.size() != 2 || !Double.isFinite(v.get(0)) || !Double.isFinite(v.get(1))) {
            LOG.warn("motion command {} is not [vMps, wRadps] with finite numbers: stopping the robot instead", command);
            stopMotion(out);
            return;
        }
        send(out, ArcosCommand.VEL.packet(velMmps(v.get(0))));
        send(out, ArcosCommand.RVEL.packet(rotVelDegps(v.get(1))));
    }

    int velMmps(double vMps) {
        double clamped = Math.max(-params.maxVelMps(), Math.min(params.maxVelMps(), vMps));
        return (int) Math.round(clamped * 1000.0);
    }

    int rotVelDegps(double wRadps) {
        double clamped = Math.max(-params.maxRotVelRadps(), Math.min(params.maxRotVelRadps(), wRadps));
        return (int) Math.round(Math.toDegrees(clamped));
    }

    /** SONAR 1 for a value of 0.5 or more, SONAR 0 below; a value that is not a finite number is refused. */
    private void writeSonarPower(Payload command, OutputStream out) throws IOException {
        if (!(command instanceof NumberValue n) || !Double.isFinite(n.value())) {
            LOG.warn("sonar-power command {} is not a finite number (1 on, 0 off): ignored", command);
            return;
        }
        send(out, ArcosCommand.SONAR.packet(n.value() >= 0.5 ? 1 : 0));
    }

    @Override
    public Optional<Duration> keepAlivePeriod() {
        return Optional.of(Duration.ofMillis(params.keepAlivePeriodMs()));
    }

    @Override
    public void keepAlive(OutputStream out) throws IOException {
        send(out, ArcosCommand.PULSE.packet());
    }

    @Override
    public void stopMotion(OutputStream out) throws IOException {
        send(out, ArcosCommand.STOP.packet());
    }

    @Override
    public void goodbye(OutputStream out) throws IOException {
        send(out, ArcosCommand.CLOSE.packet());
    }

    private static void send(OutputStream out, ArcosPacket packet) throws IOException {
        out.write(packet.toWire());
    }
}
