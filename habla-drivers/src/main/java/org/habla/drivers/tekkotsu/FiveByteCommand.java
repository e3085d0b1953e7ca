package org.habla.drivers.tekkotsu;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * One command of Tekkotsu's walk and head remote controls: a letter and a float, 5 bytes.
 * <pre>
 * +--------+-------------------------+
 * | letter | value (f32 little-end.) |
 * +--------+-------------------------+
 *   1 byte          4 bytes
 * </pre>
 * Example: {@code f 0.5} is {@code 66 00 00 00 3F}.
 *
 * @param letter the command letter ({@code 'f'}, {@code 's'}, {@code 'r'} for walking; {@code 't'},
 *               {@code 'p'}, {@code 'r'} for the head)
 * @param value  a fraction in [-1, 1]
 */
record FiveByteCommand(char letter, float value) {

    static final int BYTES = 5;

    FiveByteCommand {
        if (letter > 0x7f) {
            throw new IllegalArgumentException("command letter must be ASCII, was " + (int) letter);
        }
        if (!(value >= -1f && value <= 1f)) {
            throw new IllegalArgumentException("command value must be in [-1, 1], was " + value);
        }
    }

    /** A command whose value is {@code fraction} clamped to [-1, 1]. */
    static FiveByteCommand clamped(char letter, double fraction) {
        if (Double.isNaN(fraction)) {
            throw new IllegalArgumentException("command '" + letter + "' value is NaN");
        }
        return new FiveByteCommand(letter, (float) Math.max(-1.0, Math.min(1.0, fraction)));
    }

    /** The commands back to back, as one array. */
    static byte[] encode(FiveByteCommand... commands) {
        ByteBuffer b = ByteBuffer.allocate(commands.length * BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (FiveByteCommand c : commands) {
            b.put((byte) c.letter).putFloat(c.value);
        }
        return b.array();
    }
}
