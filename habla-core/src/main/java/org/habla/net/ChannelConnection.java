package org.habla.net;

import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.io.OutputStream;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.channels.CancelledKeyException;
import java.nio.channels.SelectionKey;
import java.nio.channels.SocketChannel;
import java.util.concurrent.locks.LockSupport;

/**
 * A plain TCP control connection as a non-blocking channel. Its streams wait like a blocking socket's, parking
 * the calling thread until {@link ChannelReadiness} says the socket can be read or written; {@link #tryWrite}
 * never waits, so an engine thread can hand a sample to a client that keeps up without waking anyone.
 */
final class ChannelConnection implements ControlConnection {

    /** A waiting thread looks again at least this often whether the connection was closed. */
    private static final long RECHECK_NANOS = 100_000_000L;

    /** One side's waiting thread and whether its readiness came. */
    private static final class Waiter {
        private final int op;
        private volatile boolean ready;
        private volatile Thread thread;

        Waiter(int op) {
            this.op = op;
        }

        void signal() {
            ready = true;
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t);
            }
        }
    }

    private final SocketChannel channel;
    private final ChannelReadiness readiness;
    private final SelectionKey key;
    private final Waiter reading = new Waiter(SelectionKey.OP_READ);
    private final Waiter writing = new Waiter(SelectionKey.OP_WRITE);
    private final InputStream in = new In();
    private final OutputStream out = new Out();
    private volatile int readTimeoutMillis;

    ChannelConnection(SocketChannel channel, ChannelReadiness readiness) throws IOException {
        this.channel = channel;
        this.readiness = readiness;
        channel.configureBlocking(false);
        this.key = readiness.register(channel, this);
    }

    /** From the selector: the socket can be read ({@code OP_READ}, also at its end) or written. */
    void ready(int ops) {
        if ((ops & SelectionKey.OP_READ) != 0) {
            reading.signal();
        }
        if ((ops & SelectionKey.OP_WRITE) != 0) {
            writing.signal();
        }
    }

    @Override
    public InputStream in() {
        return in;
    }

    @Override
    public OutputStream out() {
        return out;
    }

    @Override
    public int tryWrite(byte[] bytes) throws IOException {
        return channel.write(ByteBuffer.wrap(bytes));
    }

    @Override
    public boolean writesWithoutWaiting() {
        return true;
    }

    @Override
    public void readTimeout(int millis) {
        readTimeoutMillis = millis;
    }

    @Override
    public void shutdownOutput() throws IOException {
        channel.shutdownOutput();
    }

    @Override
    public void close() throws IOException {
        try {
            channel.close();
        } finally {
            readiness.wakeup(); // the selector lets the socket go at its next look
            reading.signal();
            writing.signal();
        }
    }

    /**
     * Parks until the selector reports {@code w}'s readiness, or until {@code deadlineNanos} (0: none).
     *
     * @return false at the deadline
     */
    private boolean await(Waiter w, long deadlineNanos) throws IOException {
        w.ready = false;
        w.thread = Thread.currentThread();
        try {
            key.interestOpsOr(w.op);
            readiness.wakeup();
            while (!w.ready) {
                if (!channel.isOpen()) {
                    throw new SocketException("Socket closed");
                }
                if (Thread.interrupted()) {
                    Thread.currentThread().interrupt();
                    throw new InterruptedIOException("interrupted while waiting for the socket");
                }
                long wait = RECHECK_NANOS;
                if (deadlineNanos != 0) {
                    long left = deadlineNanos - System.nanoTime();
                    if (left <= 0) {
                        return false;
                    }
                    wait = Math.min(wait, left);
                }
                LockSupport.parkNanos(this, wait);
            }
            return true;
        } catch (CancelledKeyException e) {
            throw new SocketException("Socket closed");
        } finally {
            w.thread = null;
        }
    }

    private final class In extends InputStream {
        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            int n = read(one, 0, 1);
            return n < 0 ? -1 : one[0] & 0xff;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            java.util.Objects.checkFromIndexSize(off, len, b.length);
            if (len == 0) {
                return 0;
            }
            ByteBuffer buffer = ByteBuffer.wrap(b, off, len);
            int timeout = readTimeoutMillis;
            long deadline = timeout > 0 ? System.nanoTime() + timeout * 1_000_000L : 0;
            while (true) {
                int n = channel.read(buffer);
                if (n != 0) {
                    return n;
                }
                if (!await(reading, deadline)) {
                    throw new SocketTimeoutException("Read timed out");
                }
            }
        }
    }

    private final class Out extends OutputStream {
        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            java.util.Objects.checkFromIndexSize(off, len, b.length);
            ByteBuffer buffer = ByteBuffer.wrap(b, off, len);
            while (buffer.hasRemaining()) {
                if (channel.write(buffer) == 0) {
                    await(writing, 0);
                }
            }
        }
    }
}
