package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.io.OutputStream;
import org.habla.sample.Payload;
import org.habla.sample.VectorValue;

/**
 * The session on the head remote control (port 10052): a {@code head} command
 * {@code [tiltRad, panRad, nodRad]} becomes the 5-byte commands {@code t}, {@code p}, {@code r}.
 *
 * <p>The robot maps a value v to the angle |v| × (v &gt; 0 ? joint max : joint min), so an angle is sent
 * as its fraction of the limit on its own side, clamped to that limit. On the ERS-7 the tilt's upper
 * limit is 0, so any upward tilt is sent as 0. The head holds its last target: no keep-alive, no stop.
 */
final class HeadSession extends CommandOnlySession {

    HeadSession() {
        super("head remote control");
    }

    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        if (!TekkotsuChannels.HEAD.equals(channel)) {
            throw new IOException("the head connection carries only '" + TekkotsuChannels.HEAD + "', not '" + channel
                    + "'");
        }
        out.write(encode(command));
    }

    /** The 15 bytes for a head command; rejects anything but three finite numbers. */
    static byte[] encode(Payload command) {
        if (!(command instanceof VectorValue v) || v.size() != 3) {
            throw new IllegalArgumentException("head takes a vector [tiltRad, panRad, nodRad], got " + command);
        }
        char[] letters = {'t', 'p', 'r'};
        FiveByteCommand[] commands = new FiveByteCommand[3];
        for (int i = 0; i < 3; i++) {
            double angle = v.get(i);
            if (!Double.isFinite(angle)) {
                throw new IllegalArgumentException("head angles must be finite numbers, got " + v);
            }
            commands[i] = FiveByteCommand.clamped(letters[i],
                    fraction(angle, Math.toRadians(Ers7.HEAD_MIN_DEG[i]), Math.toRadians(Ers7.HEAD_MAX_DEG[i])));
        }
        return FiveByteCommand.encode(commands);
    }

    /** The value v with |v| × (v &gt; 0 ? max : min) = angle, within the joint's range. */
    static double fraction(double angleRad, double minRad, double maxRad) {
        if (angleRad > 0) {
            return maxRad > 0 ? Math.min(1.0, angleRad / maxRad) : 0.0;
        }
        if (angleRad < 0) {
            return minRad < 0 ? -Math.min(1.0, angleRad / minRad) : 0.0;
        }
        return 0.0;
    }
}
