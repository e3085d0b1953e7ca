package org.habla.graph;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.TimeUnit;
import org.habla.config.ParamsJson;
import org.habla.method.Output;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.SampleCodec;
import org.habla.net.WorkerProtocol;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connection of a {@link RemotePlacement} to its worker: connects (TLS and the shared secret's proof when
 * the daemon's config asks), places the method, then carries samples both ways — the placement's queue to the
 * worker on a writer thread, the worker's output samples, heartbeats and errors back on the link's thread.
 */
final class PlacementSession implements ReconnectingLink.Session {

    /** Logged under the placement's name: one worker link, whichever class writes the line. */
    private static final Logger LOG = LoggerFactory.getLogger(RemotePlacement.class);

    private final RemotePlacement p;

    private volatile Socket socket;
    private volatile boolean closed;
    private volatile Thread writerThread;
    private FrameReader reader;

    PlacementSession(RemotePlacement placement) {
        this.p = placement;
    }

    @Override
    public void open() throws IOException {
        Socket plain = LinkSocket.create(p.reconnect.tcpKeepAlive());
        socket = plain;
        if (closed) {
            plain.close(); // the link was stopped before this socket existed: the connect below fails
        }
        plain.connect(new InetSocketAddress(p.host, p.port), (int) p.reconnect.connectTimeoutMs());
        plain.setSoTimeout((int) p.reconnect.connectTimeoutMs());
        Socket s = p.link.secure(plain, p.host, p.port, (int) p.reconnect.connectTimeoutMs());
        socket = s;
        FrameReader r = new FrameReader(new BufferedInputStream(s.getInputStream(), 65_536),
                p.limits.maxLineBytes(), p.limits.maxBinaryBytes());
        FrameWriter writer = new FrameWriter(s.getOutputStream());
        WorkerProtocol.Hello hello = WorkerProtocol.Hello.of(next(r));
        String refusal = hello.refusal(p.config.type());
        if (refusal != null) {
            throw new IOException(refusal);
        }
        WorkerProtocol.prove(hello, p.link.secret(), r, writer, p.host());
        writer.send(WorkerProtocol.place(p.config.id(), p.config.type(), p.config.layer().configName(),
                ParamsJson.write(p.config.params()), p.runner.context().channelsByInput(),
                p.runner.context().commandChannelsByOutput()));
        Frame answer = next(r);
        if (!answer.type().equals("placed")) {
            throw new IOException("the worker did not place the method: " + answer.header().path("message")
                    .asText(answer.header().toString()));
        }
        s.setSoTimeout((int) RemotePlacement.LOST_AFTER_MILLIS);
        reader = r;
        p.outbound.clear();
        writerThread = Thread.ofVirtual().name("habla-worker-out-" + p.config.id())
                .start(() -> writeLoop(writer, s));
    }

    @Override
    public void readNext() throws IOException {
        Frame f;
        try {
            f = reader.read();
        } catch (FrameException e) {
            if (e.fatal()) {
                throw e;
            }
            badLine(e.getMessage());
            return;
        }
        if (f == null) {
            throw new IOException("the worker closed the connection");
        }
        take(f);
    }

    @Override
    public void close() {
        closed = true;
        Thread w = writerThread;
        if (w != null) {
            w.interrupt();
        }
        Socket s = socket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("close: {}", e.toString());
            }
        }
    }

    private static Frame next(FrameReader reader) throws IOException {
        Frame f = reader.read();
        if (f == null) {
            throw new IOException("the worker closed the connection");
        }
        return f;
    }

    private void take(Frame f) {
        switch (f.type()) {
            case "sample" -> {
                String name = f.header().path("output").asText("");
                Output<?> out = p.runner.method().output(name).orElse(null);
                if (out == null) {
                    badLine("a sample of an unknown output '" + name + "'");
                    return;
                }
                try {
                    Payload value = SampleCodec.value(f, out.kind());
                    p.received.incrementAndGet();
                    // published on the method's own port, as if the method had emitted it here
                    p.runner.context().emit(out, value, f.header().path("t").asLong(0));
                } catch (FrameException | RuntimeException e) {
                    badLine(e.getMessage());
                }
            }
            case "heartbeat" -> {
                boolean ready = f.header().path("ready").asBoolean(true);
                String detail = f.header().path("readiness").asText("");
                p.runner.context().readiness(ready, detail.isEmpty() ? "" : "on worker " + p.host() + ": " + detail);
            }
            case "error" -> badLine(f.header().path("code").asText("") + ": " + f.header().path("message").asText(""));
            default -> badLine("an unexpected line of type '" + f.type() + "'");
        }
    }

    private void badLine(String what) {
        long n = p.badLines.incrementAndGet();
        if (n == 1 || n % 1_000 == 0) {
            LOG.warn("worker {} of method {}: {} ({} so far)", p.host(), p.config.id(), what, n);
        }
    }

    private void writeLoop(FrameWriter writer, Socket s) {
        try {
            while (p.connection.running()) {
                Frame f = p.outbound.poll(250, TimeUnit.MILLISECONDS);
                if (f == null) {
                    continue;
                }
                do {
                    writer.write(f);
                    p.sent.incrementAndGet();
                    f = p.outbound.poll();
                } while (f != null);
                writer.flush();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("writing to worker {} failed: {}", p.host(), e.toString());
            try {
                s.close();
            } catch (IOException ignored) {
                // the reader notices the closed socket
            }
        }
    }
}
