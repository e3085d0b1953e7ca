package org.habla.net;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.Charset;
import java.util.Arrays;
import java.util.Objects;

/**
 * The first stage of every HABLA socket, and the line reader of every line protocol HABLA speaks (the text-lines
 * driver, Tekkotsu's controller and emergency stop, the simulator's servers) and of its recordings: a bounded,
 * blocking line reader over a byte stream. It hands out one line's bytes at a time (the {@code \n}, and a {@code \r} before
 * it, removed), or its text in a given charset, and the raw block that may follow a line, from the same buffer.
 *
 * <pre>
 *   bytes:  h i \r \n   l o n g … (more than maxLineBytes) … \n   o k \n
 *   lines:  "hi"        line_too_long (recoverable)              "ok"
 * </pre>
 *
 * <p>A line longer than {@code maxLineBytes} is never held: its bytes are discarded up to and including the
 * next newline, then a recoverable {@code line_too_long} error names the limit, and the next call reads the
 * next line. The limit does not count the line's end: a {@code \r} before the {@code \n} is free. A protocol
 * where only a bare {@code \n} ends a line (Tekkotsu's emergency stop: {@code stop\r} is not {@code stop}) reads
 * through {@link #keepingCarriageReturns}, which hands a {@code \r} out as part of the line and counts it.
 *
 * <p>{@link #position()} says how many bytes of the stream the lines and blocks handed out so far (and the lines
 * discarded) took, so a reader of a file knows where each record starts.
 *
 * <p>A block's memory is reserved from a {@link BlockBudget} as its bytes arrive, growing by doubling from
 * {@link #FIRST_BLOCK_BYTES}: a declared size is never allocated before the bytes are there.
 *
 * <p>Not thread-safe: one reader thread per stream; only {@link #frameSinceNanos()} may be read by others
 * (a watchdog of slow frames).
 */
public final class LineFramer {

    /** The read buffer grows to this while reads fill it; an idle stream holds only the first size. */
    private static final int BUFFER_BYTES = 8_192;
    private static final int FIRST_BUFFER_BYTES = 512;
    /** The room reserved for a block when its first bytes arrive; it doubles as more come. */
    static final int FIRST_BLOCK_BYTES = 65_536;
    private static final byte[] NO_BYTES = new byte[0];

    private final InputStream in;
    private final int maxLineBytes;
    /** Whether a {@code \r} before the {@code \n} is part of the line (and of its length). */
    private final boolean keepCarriageReturn;
    private byte[] buf = new byte[FIRST_BUFFER_BYTES];
    private int pos;
    private int end;
    /** Bytes read from the stream so far, into the buffer or straight into a block. */
    private long streamBytes;
    /** When the frame being read got its first byte ({@link System#nanoTime()}), or 0 between frames. */
    private volatile long frameSince;

    /**
     * A framer over {@code in}, which it then owns: it reads ahead into its own buffer, so every later read of
     * the stream must go through it.
     */
    public LineFramer(InputStream in, int maxLineBytes) {
        this(in, maxLineBytes, false);
    }

    private LineFramer(InputStream in, int maxLineBytes, boolean keepCarriageReturn) {
        this.in = Objects.requireNonNull(in, "in");
        if (maxLineBytes < 1) {
            throw new IllegalArgumentException("maxLineBytes must be at least 1, was " + maxLineBytes);
        }
        this.maxLineBytes = maxLineBytes;
        this.keepCarriageReturn = keepCarriageReturn;
    }

    /**
     * A framer whose lines end at a bare {@code \n} only: a {@code \r} before it stays in the line and counts
     * towards {@code maxLineBytes}.
     */
    public static LineFramer keepingCarriageReturns(InputStream in, int maxLineBytes) {
        return new LineFramer(in, maxLineBytes, true);
    }

    /** The bytes of the stream taken so far by the lines and blocks handed out, and by what was discarded. */
    public long position() {
        return streamBytes - (end - pos);
    }

    /** The longest line, in bytes without its end, that {@link #readLine} hands out. */
    public int maxLineBytes() {
        return maxLineBytes;
    }

    /**
     * Reads the next line as text in {@code charset} (bytes it cannot map become its replacement character).
     *
     * @return the line without its end, or {@code null} at a clean end of stream (between lines)
     * @throws FrameException as {@link #readLine()}
     * @throws IOException    if the stream fails
     */
    public String readText(Charset charset) throws IOException {
        byte[] line = readLine();
        return line == null ? null : new String(line, charset);
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
        int endSlack = keepCarriageReturn ? 0 : 1;
        byte[] line = new byte[Math.min(256, maxLineBytes + endSlack)];
        int length = 0;
        while (true) {
            if (pos == end && !fill()) {
                if (length == 0) {
                    return null;
                }
                throw FrameException.fatal("truncated",
                        "the stream ended inside a line: " + length + " byte(s) dropped");
            }
            if (frameSince == 0) {
                frameSince = System.nanoTime();
            }
            int newline = indexOfNewline();
            int stop = newline < 0 ? end : newline;
            int take = stop - pos;
            // The line may carry one '\r' beyond maxLineBytes (unless it keeps it); anything more is too long.
            if (length + take > maxLineBytes + endSlack) {
                pos = stop;
                discardThroughNewline(newline >= 0);
                throw FrameException.recoverable("line_too_long",
                        "line longer than maxLineBytes=" + maxLineBytes + " bytes; discarded");
            }
            if (length + take > line.length) {
                line = Arrays.copyOf(line, Math.min(maxLineBytes + endSlack, Math.max(line.length * 2, length + take)));
            }
            System.arraycopy(buf, pos, line, length, take);
            length += take;
            pos = stop;
            if (newline >= 0) {
                pos++;
                if (!keepCarriageReturn && length > 0 && line[length - 1] == '\r') {
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
     * Reads exactly {@code count} raw bytes (the block after a line), with no bound on the memory it holds.
     *
     * @throws EOFException if the stream ends first
     */
    public byte[] readBytes(int count) throws IOException {
        return readBytes(count, BlockBudget.unbounded());
    }

    /**
     * Reads exactly {@code count} raw bytes (the block after a line), reserving room from {@code budget} only
     * as the bytes arrive; the reservation is given back when the block is whole or abandoned.
     *
     * @throws FrameException {@code block_budget} (recoverable: the rest of the block has been read and
     *                        discarded, the stream is at the next frame) when the budget has no room
     * @throws EOFException   if the stream ends first
     */
    public byte[] readBytes(int count, BlockBudget budget) throws IOException {
        if (count == 0) {
            return NO_BYTES;
        }
        byte[] out = NO_BYTES;
        int have = 0;
        long held = 0;
        try {
            while (have < count) {
                if (pos == end && !fill()) {
                    throw new EOFException("the stream ended after " + have + " of " + count + " bytes");
                }
                if (have == out.length) {
                    int room = (int) Math.min(count, Math.max(FIRST_BLOCK_BYTES, 2L * have));
                    try {
                        budget.reserve(room - held);
                    } catch (FrameException full) {
                        budget.release(held);
                        held = 0;
                        out = NO_BYTES;
                        skip(count - have);
                        throw full;
                    }
                    held = room;
                    out = Arrays.copyOf(out, room);
                }
                int take = Math.min(end - pos, out.length - have);
                System.arraycopy(buf, pos, out, have, take);
                pos += take;
                have += take;
                if (pos == end && have < out.length) {
                    int n = in.read(out, have, out.length - have);
                    if (n < 0) {
                        throw new EOFException("the stream ended after " + have + " of " + count + " bytes");
                    }
                    streamBytes += n;
                    have += n;
                }
            }
            return out;
        } finally {
            budget.release(held);
        }
    }

    /** Reads and drops {@code count} bytes, holding no more than the line buffer. */
    private void skip(long count) throws IOException {
        long left = count;
        while (left > 0) {
            if (pos == end && !fill()) {
                throw FrameException.fatal("truncated", "the stream ended inside a binary block, "
                        + left + " bytes short");
            }
            int take = (int) Math.min(left, end - pos);
            pos += take;
            left -= take;
        }
    }

    /**
     * When the frame being read got its first byte, as {@link System#nanoTime()}, or 0 while waiting between
     * frames. Safe to call from any thread.
     */
    public long frameSinceNanos() {
        return frameSince;
    }

    /** Marks the end of a frame (read whole, or skipped after an error): the next byte starts the next one. */
    public void frameDone() {
        frameSince = 0;
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
        if (end == buf.length && buf.length < BUFFER_BYTES) {
            buf = new byte[Math.min(BUFFER_BYTES, buf.length * 4)]; // the last read filled it: more is coming
        }
        int n = in.read(buf, 0, buf.length);
        while (n == 0) {
            n = in.read(buf, 0, buf.length);
        }
        if (n < 0) {
            pos = end = 0;
            return false;
        }
        streamBytes += n;
        pos = 0;
        end = n;
        return true;
    }
}
