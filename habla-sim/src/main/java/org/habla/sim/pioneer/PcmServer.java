package org.habla.sim.pioneer;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A raw PCM stream server, what {@code arecord -f S16_LE -r 16000 -c 1 -t raw | nc -l 8110} is on the real robot's
 * laptop: one client at a time receives the audio from the moment it connects, with no header. A new client
 * takes over from the old one. Audio the client does not read in time is dropped (counted), never queued without
 * bound; while nobody listens, the audio is simply not kept.
 */
final class PcmServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PcmServer.class);
    /** Chunks (one sim step each) waiting for the client: 2 s of audio at 10 ms steps. */
    static final int OUTBOX_CHUNKS = 200;

    private final ServerSocket listener;
    private volatile boolean closed;
    private volatile Listener current;
    private final LongAdder droppedChunks = new LongAdder();

    PcmServer(int port) throws IOException {
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 4);
        } catch (IOException e) {
            server.close();
            throw new IOException("the microphone stream cannot listen on 127.0.0.1:" + port + ": " + e.getMessage(), e);
        }
        listener = server;
        Thread acceptor = new Thread(this::acceptLoop, "mic-accept");
        acceptor.setDaemon(true);
        acceptor.start();
        LOG.info("microphone stream (16 kHz s16le mono) on 127.0.0.1:{}", server.getLocalPort());
    }

    int port() {
        return listener.getLocalPort();
    }

    long droppedChunks() {
        return droppedChunks.sum();
    }

    /** Whether a client is connected. */
    boolean listening() {
        return current != null;
    }

    /** Hands one chunk of audio to the client, if there is one; never blocks. */
    void send(byte[] pcm) {
        Listener l = current;
        if (l != null && !l.outbox.offer(pcm)) {
            droppedChunks.increment();
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            listener.close();
        } catch (IOException e) {
            LOG.debug("closing the microphone stream: {}", e.toString());
        }
        Listener l = current;
        if (l != null) {
            l.close();
        }
    }

    private void acceptLoop() {
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("the microphone stream stopped accepting: {}", e.toString());
                }
                return;
            }
            Listener old = current;
            if (old != null) {
                old.close();
            }
            Listener l = new Listener(socket);
            current = l;
            Thread.ofVirtual().name("mic-write").start(l::writeLoop);
            Thread.ofVirtual().name("mic-drain").start(l::drainLoop);
        }
    }

    private final class Listener {
        private final Socket socket;
        private final BlockingQueue<byte[]> outbox = new ArrayBlockingQueue<>(OUTBOX_CHUNKS);
        private volatile boolean gone;

        Listener(Socket socket) {
            this.socket = socket;
        }

        void writeLoop() {
            try {
                OutputStream out = socket.getOutputStream();
                while (!gone) {
                    byte[] chunk = outbox.poll(200, TimeUnit.MILLISECONDS);
                    if (chunk != null) {
                        out.write(chunk);
                        if (outbox.isEmpty()) {
                            out.flush();
                        }
                    }
                }
            } catch (IOException e) {
                LOG.info("microphone client {} left: {}", socket.getRemoteSocketAddress(), e.toString());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                close();
            }
        }

        /**
         * Reads and ignores whatever the client sends. An end of its input is no goodbye (a client may half-close
         * and keep listening); a failed write is.
         */
        void drainLoop() {
            try {
                InputStream in = socket.getInputStream();
                byte[] sink = new byte[512];
                while (!gone && in.read(sink) >= 0) {
                    // ignored: the microphone only talks
                }
            } catch (IOException e) {
                LOG.debug("microphone client read: {}", e.toString());
                close();
            }
        }

        void close() {
            gone = true;
            if (current == this) {
                current = null;
            }
            try {
                socket.close();
            } catch (IOException e) {
                LOG.debug("closing a microphone client: {}", e.toString());
            }
        }
    }
}
