package org.habla.net;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import java.util.Objects;

/**
 * The first stage of every HABLA socket: a bounded, blocking line reader over a byte stream. It hands out
 * one line's bytes at a time (the {@code \n}, and a {@code \r} before it, removed), and the raw block that
 * may follow a line, from the same buffer.
 *
 * <p>A line longer than {@code maxLineBytes} is never held: its bytes are discarded up to and including the
 * next newline, then a recoverable {@code line_too_long} error names the limit, and the next call reads the
 * next line. Not thread-safe: one reader thread per stream.
 */
public final class LineFramer {

    private static final int BUFFER_BYTES = 8_192;

    private final InputStream in;
    private final int maxLineBytes;
    private final byte[] buf = new byte[BUFFER_BYTES];
    private int pos;
    private int end;

    public LineFramer(InputStream in, int maxLineBytes) {
        this.in = Objects.requireNonNull(in, "in");
        if (maxLineBytes < 2) {
            throw new IllegalArgumentException("maxLineBytes must be at least 2, was " + maxLineBytes);
        }
        this.maxLineBytes = maxLineBytes;
    }

    /**
     * Reads the next line.
     *
     * @return the line's bytes without its end, or {@code null} at a clean end of stream (between lines)
     * @throws FrameException {@code line_too_long} (recoverable) or {@code truncated} (fatal: the stream
     *                        ended inside a line)
     * @throws IOException    if the stream fails
     */
    public byte[] readLine() throws IOException {
        byte[] line = new byte[Math.min(256, maxLineBytes + 1)];
        int length = 0;
        while (true) {
            if (pos == end && !fill()) {
                if (length == 0) {
                    return null;
                }
                throw FrameException.fatal("truncated", "the stream ended inside a line, after " + length + " bytes");
            }
            int newline = indexOfNewline();
            int stop = newline < 0 ? end : newline;
            int take = stop - pos;
            // The line may carry one '\r' beyond maxLineBytes; anything more is too long.
            if (length + take > maxLineBytes + 1) {
                pos = stop;
                discardThroughNewline(newline >= 0);
                throw FrameException.recoverable("line_too_long",
                        "line longer than maxLineBytes=" + maxLineBytes + " bytes; discarded");
            }
            if (length + take > line.length) {
                line = Arrays.copyOf(line, Math.min(maxLineBytes + 1, Math.max(line.length * 2, length + take)));
            }
            System.arraycopy(buf, pos, line, length, take);
            length += take;
            pos = stop;
            if (newline >= 0) {
                pos++;
                if (length > 0 && line[length - 1] == '\r') {
                    length--;
                }
                if (length > maxLineBytes) {
                    throw FrameException.recoverable("line_too_long",
                            "line longer than maxLineBytes=" + maxLineBytes + " bytes; discarded");
                }
                return Arrays.copyOf(line, length);
            }
        }
    }

    /**
     * Reads exactly {@code count} raw bytes (the block after a line).
     *
     * @throws EOFException if the stream ends first
     */
    public byte[] readBytes(int count) throws IOException {
        byte[] out = new byte[count];
        int have = Math.min(count, end - pos);
        System.arraycopy(buf, pos, out, 0, have);
        pos += have;
        while (have < count) {
            int n = in.read(out, have, count - have);
            if (n < 0) {
                throw new EOFException("the stream ended after " + have + " of " + count + " bytes");
            }
            have += n;
        }
        return out;
    }

    private void discardThroughNewline(boolean atNewline) throws IOException {
        while (true) {
            if (atNewline) {
                pos++;
                return;
            }
            pos = end;
            if (!fill()) {
                throw FrameException.fatal("line_too_long", "line longer than maxLineBytes=" + maxLineBytes
                        + " bytes, and the stream ended before its end");
            }
            int newline = indexOfNewline();
            if (newline >= 0) {
                pos = newline;
                atNewline = true;
            }
        }
    }

    private int indexOfNewline() {
        for (int i = pos; i < end; i++) {
            if (buf[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    private boolean fill() throws IOException {
        int n = in.read(buf, 0, buf.length);
        while (n == 0) {
            n = in.read(buf, 0, buf.length);
        }
        if (n < 0) {
            pos = end = 0;
            return false;
        }
        pos = 0;
        end = n;
        return true;
    }
}
