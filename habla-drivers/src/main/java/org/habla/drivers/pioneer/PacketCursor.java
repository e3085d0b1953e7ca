package org.habla.drivers.pioneer;

/**
 * Reads the little-endian fields of one packet's payload in order. Reading past the end throws an
 * {@link IllegalArgumentException} that names the field, so a truncated packet is reported, not guessed.
 */
final class PacketCursor {

    private final byte[] bytes;
    private int at;

    PacketCursor(byte[] bytes) {
        this.bytes = bytes;
    }

    int remaining() {
        return bytes.length - at;
    }

    int u8(String field) {
        need(1, field);
        return bytes[at++] & 0xFF;
    }

    int s8(String field) {
        need(1, field);
        return bytes[at++];
    }

    int u16(String field) {
        need(2, field);
        int v = (bytes[at] & 0xFF) | ((bytes[at + 1] & 0xFF) << 8);
        at += 2;
        return v;
    }

    int s16(String field) {
        return (short) u16(field);
    }

    long u32(String field) {
        need(4, field);
        long v = (bytes[at] & 0xFFL) | ((bytes[at + 1] & 0xFFL) << 8) | ((bytes[at + 2] & 0xFFL) << 16)
                | ((bytes[at + 3] & 0xFFL) << 24);
        at += 4;
        return v;
    }

    private void need(int n, String field) {
        if (at + n > bytes.length) {
            throw new IllegalArgumentException("packet of " + bytes.length + " payload bytes ends inside " + field
                    + " (offset " + at + ")");
        }
    }
}
