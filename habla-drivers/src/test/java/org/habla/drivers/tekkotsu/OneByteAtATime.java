package org.habla.drivers.tekkotsu;

import java.io.ByteArrayInputStream;
import java.io.InputStream;

/** An input stream that hands out at most one byte per read, like a TCP stream split everywhere. */
final class OneByteAtATime extends InputStream {

    private final ByteArrayInputStream bytes;

    OneByteAtATime(byte[] data) {
        this.bytes = new ByteArrayInputStream(data);
    }

    @Override
    public int read() {
        return bytes.read();
    }

    @Override
    public int read(byte[] b, int off, int len) {
        return len == 0 ? 0 : bytes.read(b, off, 1);
    }
}
