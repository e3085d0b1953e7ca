package org.habla.sim.aibo;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Reads the walk and head remote controls' commands: a letter and a little-endian float, 5 bytes,
 * back to back with no separators. Commands split across TCP segments are put back together.
 */
final class FiveByteInput {

    /** One command. */
    record Command(char letter, float value) {
    }

    private final DataInputStream in;
    private final byte[] buffer = new byte[5];

    FiveByteInput(InputStream in) {
        this.in = new DataInputStream(in);
    }

    /** The next command, or null when the client has gone (a partial command at the end is dropped). */
    Command next() throws IOException {
        try {
            in.readFully(buffer);
        } catch (EOFException e) {
            return null;
        }
        float value = ByteBuffer.wrap(buffer, 1, 4).order(ByteOrder.LITTLE_ENDIAN).getFloat();
        return new Command((char) (buffer[0] & 0xff), value);
    }
}
