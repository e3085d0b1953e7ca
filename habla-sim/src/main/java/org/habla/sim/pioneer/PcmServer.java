package org.habla.sim.pioneer;

import java.io.IOException;
import java.io.InputStream;
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

    private final OneClientPort port;

    PcmServer(int port) throws IOException {
        this.port = new OneClientPort("the microphone stream", "mic", port, OUTBOX_CHUNKS, PcmServer::drain, c -> { },
                c -> { });
        LOG.info("microphone stream (16 kHz s16le mono) on 127.0.0.1:{}", this.port.port());
    }

    int port() {
        return port.port();
    }

    long droppedChunks() {
        return port.dropped();
    }

    /** Whether a client is connected. */
    boolean listening() {
        return port.connected();
    }

    /** Hands one chunk of audio to the client, if there is one; never blocks. */
    void send(byte[] pcm) {
        port.send(pcm);
    }

    /**
     * Reads and ignores whatever the client sends. An end of its input is no goodbye (a client may half-close
     * and keep listening): the client goes when a write to it fails.
     */
    private static void drain(OneClientPort.Client client, InputStream in) throws IOException {
        byte[] sink = new byte[512];
        while (!client.gone() && in.read(sink) >= 0) {
            // ignored: the microphone only talks
        }
        while (!client.gone()) {
            try {
                Thread.sleep(200);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    @Override
    public void close() {
        port.close();
    }
}
