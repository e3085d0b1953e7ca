package org.habla.sim.pioneer;

import java.util.OptionalInt;

/**
 * Reads the argument of a client command the way the controller does: {@code 0x3B} and a little-endian value,
 * or {@code 0x1B} and the magnitude of a negative value; a packet with no argument, or a malformed one, has none.
 */
final class ArcosArgs {

    static final int ARG_INT = 0x3B;
    static final int ARG_NEG_INT = 0x1B;
    static final int ARG_STR = 0x2B;

    private ArcosArgs() {
    }

    /** The integer argument of {@code data} (command byte first), if it carries one. */
    static OptionalInt intArg(byte[] data) {
        if (data.length < 4) {
            return OptionalInt.empty();
        }
        int magnitude = (data[2] & 0xFF) | ((data[3] & 0xFF) << 8);
        return switch (data[1] & 0xFF) {
            case ARG_INT -> OptionalInt.of(magnitude);
            case ARG_NEG_INT -> OptionalInt.of(-magnitude);
            default -> OptionalInt.empty();
        };
    }
}
