package org.habla.net;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;

/**
 * The byte streams of one served control connection, and, where the socket allows it, a write that never waits.
 * A plain TCP connection is a non-blocking channel ({@link ChannelConnection}): its streams wait for readiness
 * like a blocking socket's, and an engine thread may hand a sample straight to the socket with
 * {@link #tryWrite} when nothing else is queued for that client. A TLS connection is a {@link Socket}'s
 * streams ({@link #of(Socket)}), and {@link #tryWrite} writes nothing.
 */
interface ControlConnection {

    /** Reads block until bytes arrive, the peer ends, or the read timeout passes ({@link java.net.SocketTimeoutException}). */
    InputStream in() throws IOException;

    /** Writes block until the socket has taken every byte. */
    OutputStream out() throws IOException;

    /**
     * Writes what the socket takes of {@code bytes} now, without waiting; the caller owns the writing side
     * while it does.
     *
     * @return how many bytes the socket took (0 when it has no room, or when this connection cannot write
     *         without waiting)
     */
    int tryWrite(byte[] bytes) throws IOException;

    /** Whether {@link #tryWrite} can write at all. */
    boolean writesWithoutWaiting();

    /** How long a read may wait, in milliseconds (0: for ever). */
    void readTimeout(int millis) throws IOException;

    void shutdownOutput() throws IOException;

    void close() throws IOException;

    /** A connection over a socket's own streams (TLS): every write may wait. */
    static ControlConnection of(Socket socket) {
        return new ControlConnection() {
            @Override
            public InputStream in() throws IOException {
                return socket.getInputStream();
            }

            @Override
            public OutputStream out() throws IOException {
                return socket.getOutputStream();
            }

            @Override
            public int tryWrite(byte[] bytes) {
                return 0;
            }

            @Override
            public boolean writesWithoutWaiting() {
                return false;
            }

            @Override
            public void readTimeout(int millis) throws IOException {
                socket.setSoTimeout(millis);
            }

            @Override
            public void shutdownOutput() throws IOException {
                socket.shutdownOutput();
            }

            @Override
            public void close() throws IOException {
                socket.close();
            }
        };
    }
}
