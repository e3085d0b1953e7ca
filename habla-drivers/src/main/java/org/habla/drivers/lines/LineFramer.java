package org.habla.drivers.lines;

import java.util.Arrays;

/**
 * Cuts a byte stream into lines at {@code \n}, bounded: bytes are pushed in as they arrive and each whole
 * line comes out without its {@code \n} (and without a {@code \r} before it).
 *
 * <pre>
 *   bytes:  h i \r \n   l o n g … (more than maxLineBytes) … \n   o k \n
 *   lines:  "hi"        (dropped, reported once)                 "ok"
 * </pre>
 *
 * A line longer than {@code maxLineBytes} (not counting the line end) is dropped whole: the framer
 * reports it and skips to the next {@code \n}, so memory stays bounded whatever the peer sends.
 *
 * <p>Not thread-safe: one framer per connection, used by its reader.
 */
final class LineFramer {

    /** What the framer hands out. */
    interface Listener {
        /** One line's bytes, line end removed. */
        void line(byte[] bytes);

        /** A line over the limit was dropped. */
        void overlong(int maxLineBytes);
    }

    private final int maxLineBytes;
    private final byte[] line;
    private int length;
    private boolean discarding;

    LineFramer(int maxLineBytes) {
        if (maxLineBytes < 1) {
            throw new IllegalArgumentException("maxLineBytes must be at least 1, was " + maxLineBytes);
        }
        this.maxLineBytes = maxLineBytes;
        // one more for a '\r' that may turn out to end the line
        this.line = new byte[maxLineBytes + 1];
    }

    void push(byte[] bytes, int offset, int count, Listener listener) {
        for (int i = offset; i < offset + count; i++) {
            byte b = bytes[i];
            if (b == '\n') {
                endLine(listener);
            } else if (!discarding) {
                if (length == line.length) {
                    discarding = true;
                    length = 0;
                    listener.overlong(maxLineBytes);
                } else {
                    line[length++] = b;
                }
            }
        }
    }

    /** Bytes of an unfinished line held. */
    int pending() {
        return length;
    }

    private void endLine(Listener listener) {
        if (discarding) {
            discarding = false;
            length = 0;
            return;
        }
        int end = length > 0 && line[length - 1] == '\r' ? length - 1 : length;
        length = 0;
        if (end > maxLineBytes) {
            listener.overlong(maxLineBytes);
            return;
        }
        listener.line(Arrays.copyOf(line, end));
    }
}
