package org.habla.net;

import java.io.ByteArrayInputStream;
import java.io.InputStream;

/** An input stream over fixed bytes that hands out at most one byte per read, the worst split a socket can do. */
final class TrickleInputStream extends InputStream {

    private final ByteArrayInputStream bytes;

    TrickleInputStream(byte[] data) {
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
