package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.time.Duration;
import java.util.Optional;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;
import org.habla.sample.VectorValue;

/**
 * The session on the walk remote control (port 10050): a {@code walk} command
 * {@code [forwardMps, strafeMps, rotateRadps]} becomes the three 5-byte commands {@code f}, {@code s},
 * {@code r}, each a fraction of the walk's maximum speed clamped to [-1, 1].
 *
 * <p>The robot zeroes the walk after 3 s without a command, so the standing command is re-sent by
 * {@link #keepAlive} (every {@code walkResendMs}); {@link #stopMotion} and {@link #goodbye} send zeros.
 */
final class WalkSession extends CommandOnlySession {

    private final WalkLimits limits;
    private final Duration resendPeriod;
    /** The last fractions sent; written under the link's write lock, read by it too. */
    private volatile byte[] standing = zeros();

    /** The speeds at fraction ±1. */
    record WalkLimits(double forwardMps, double reverseMps, double strafeMps, double rotateRadps) {
    }

    WalkSession(WalkLimits limits, Duration resendPeriod) {
        super("walk remote control");
        this.limits = limits;
        this.resendPeriod = resendPeriod;
    }

    /** A clean start: a previous client may have left the robot walking. */
    @Override
    public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
        stopMotion(out);
    }

    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        if (!TekkotsuChannels.WALK.equals(channel)) {
            throw new IOException("the walk connection carries only '" + TekkotsuChannels.WALK + "', not '" + channel
                    + "'");
        }
        byte[] bytes = encode(command);
        out.write(bytes);
        standing = bytes;
    }

    /** The 15 bytes for a walk command; rejects anything but three finite numbers. */
    byte[] encode(Payload command) {
        if (!(command instanceof VectorValue v) || v.size() != 3) {
            throw new IllegalArgumentException("walk takes a vector [forwardMps, strafeMps, rotateRadps], got "
                    + command);
        }
        double forward = v.get(0);
        double strafe = v.get(1);
        double rotate = v.get(2);
        if (!Double.isFinite(forward) || !Double.isFinite(strafe) || !Double.isFinite(rotate)) {
            throw new IllegalArgumentException("walk values must be finite numbers, got " + v);
        }
        double forwardFraction = forward / (forward > 0 ? limits.forwardMps() : limits.reverseMps());
        return FiveByteCommand.encode(
                FiveByteCommand.clamped('f', forwardFraction),
                FiveByteCommand.clamped('s', strafe / limits.strafeMps()),
                FiveByteCommand.clamped('r', rotate / limits.rotateRadps()));
    }

    @Override
    public Optional<Duration> keepAlivePeriod() {
        return Optional.of(resendPeriod);
    }

    @Override
    public void keepAlive(OutputStream out) throws IOException {
        out.write(standing);
    }

    @Override
    public void stopMotion(OutputStream out) throws IOException {
        byte[] stop = zeros();
        out.write(stop);
        standing = stop;
    }

    @Override
    public void goodbye(OutputStream out) throws IOException {
        stopMotion(out);
    }

    private static byte[] zeros() {
        return FiveByteCommand.encode(new FiveByteCommand('f', 0f), new FiveByteCommand('s', 0f),
                new FiveByteCommand('r', 0f));
    }
}
