package org.habla.drivers.tekkotsu;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * A reader of Tekkotsu's little-endian binary fields from a stream. Every read either returns the
 * whole field or throws: {@link EOFException} naming the field when the peer stops mid-packet,
 * {@link MalformedFieldException} when a length or string breaks a stated limit.
 */
final class WireInput {

    private final InputStream in;

    WireInput(InputStream in) {
        this.in = in;
    }

    /** One byte, 0..255. */
    int u8(String field) throws IOException {
        int b = in.read();
        if (b < 0) {
            throw new EOFException("stream ended while reading " + field);
        }
        return b;
    }

    int u16(String field) throws IOException {
        byte[] b = bytes(2, field);
        return (b[0] & 0xff) | (b[1] & 0xff) << 8;
    }

    /** A 32-bit little-endian integer as a signed int. */
    int i32(String field) throws IOException {
        byte[] b = bytes(4, field);
        return (b[0] & 0xff) | (b[1] & 0xff) << 8 | (b[2] & 0xff) << 16 | (b[3] & 0xff) << 24;
    }

    /** A 32-bit little-endian unsigned integer. */
    long u32(String field) throws IOException {
        return i32(field) & 0xffff_ffffL;
    }

    float f32(String field) throws IOException {
        return Float.intBitsToFloat(i32(field));
    }

    /** Exactly {@code n} bytes. */
    byte[] bytes(int n, String field) throws IOException {
        byte[] b = in.readNBytes(n);
        if (b.length != n) {
            throw new EOFException("stream ended while reading " + field + " (" + b.length + " of " + n + " bytes)");
        }
        return b;
    }

    void skip(long n, String field) throws IOException {
        long left = n;
        while (left > 0) {
            byte[] b = in.readNBytes((int) Math.min(left, 8192));
            if (b.length == 0) {
                throw new EOFException("stream ended while skipping " + field);
            }
            left -= b.length;
        }
    }

    /** ASCII text up to a NUL byte (which is consumed), at most {@code maxChars} printable characters. */
    String cString(int maxChars, String field) throws IOException {
        StringBuilder s = new StringBuilder();
        while (true) {
            int b = u8(field);
            if (b == 0) {
                return s.toString();
            }
            if (b < 0x20 || b > 0x7e || s.length() == maxChars) {
                throw new MalformedFieldException(field + " is not a NUL-terminated ASCII text of at most " + maxChars
                        + " characters (read '" + s + "' then byte 0x" + Integer.toHexString(b) + ")");
            }
            s.append((char) b);
        }
    }

    /**
     * A "LoadSave string": {@code uint32 length}, the characters, one NUL.
     * <pre>
     * +----------------+----------------+----+
     * | length (LE u32)| length chars   | 00 |
     * +----------------+----------------+----+
     * </pre>
     */
    String loadSaveString(int maxChars, String field) throws IOException {
        long length = u32(field + " length");
        if (length > maxChars) {
            throw new MalformedFieldException(field + " claims " + length + " characters, more than the limit of "
                    + maxChars);
        }
        byte[] b = bytes((int) length + 1, field);
        if (b[(int) length] != 0) {
            throw new MalformedFieldException(field + " is not followed by its NUL byte");
        }
        return new String(b, 0, (int) length, StandardCharsets.ISO_8859_1);
    }

    /**
     * Reads on until {@code marker} has gone by (it is consumed), to find the next packet after garbage.
     * Returns how many bytes were skipped before the marker; throws if it is not found within
     * {@code maxBytes}, because then the stream is not the protocol it should be.
     */
    long skipPast(byte[] marker, int maxBytes, String what) throws IOException {
        byte[] window = new byte[marker.length];
        long read = 0;
        while (read < maxBytes + marker.length) {
            int b = in.read();
            if (b < 0) {
                throw new EOFException("stream ended while looking for the start of " + what);
            }
            System.arraycopy(window, 1, window, 0, window.length - 1);
            window[window.length - 1] = (byte) b;
            read++;
            if (read >= marker.length && java.util.Arrays.equals(window, marker)) {
                return read - marker.length;
            }
        }
        throw new IOException("no start of " + what + " within " + maxBytes + " bytes: the stream is not "
                + what + "s");
    }

    /** A field whose value breaks the format: the packet is garbage, the stream may still be recoverable. */
    static final class MalformedFieldException extends IOException {
        private static final long serialVersionUID = 1L;

        MalformedFieldException(String message) {
            super(message);
        }
    }

    /** At most 60 characters of {@code text}, for messages about bad input. */
    static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 60) + "…";
    }
}
