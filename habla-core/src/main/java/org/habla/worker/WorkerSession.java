package org.habla.worker;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.Socket;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import org.habla.config.ConfigError;
import org.habla.config.ConfigException;
import org.habla.config.Limits;
import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.graph.EngineClock;
import org.habla.graph.HostedMethod;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.SampleCodec;
import org.habla.net.WorkerProtocol;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One daemon connection to a worker, carrying one placed method (see {@link WorkerProtocol}): says hello,
 * makes the method the daemon asks for, feeds it the samples that arrive and sends back what it publishes.
 * Outgoing lines wait in a bounded queue for one writer thread, which also sends the heartbeat; a full
 * queue drops the newest output sample and counts it. A bad line gets an error line and is skipped.
 */
final class WorkerSession implements Runnable {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerSession.class);
    /** How long a new connection may take to say which method to run. */
    static final int PLACE_TIMEOUT_MILLIS = 10_000;
    /** Output lines waiting for the daemon; more are dropped and counted. */
    static final int QUEUE_FRAMES = 256;

    private final Socket socket;
    private final PluginRegistry registry;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final Limits limits;
    private final ArrayBlockingQueue<Frame> outbound = new ArrayBlockingQueue<>(QUEUE_FRAMES);
    private final AtomicLong dropped = new AtomicLong();
    private volatile boolean open = true;
    private HostedMethod hosted;
    private String methodId = "?";

    WorkerSession(Socket socket, PluginRegistry registry, EngineClock clock, ExecutorService backgroundPool,
            Limits limits) {
        this.socket = socket;
        this.registry = registry;
        this.clock = clock;
        this.backgroundPool = backgroundPool;
        this.limits = limits;
    }

    @Override
    public void run() {
        String peer = String.valueOf(socket.getRemoteSocketAddress());
        Thread writer = null;
        try (socket) {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(PLACE_TIMEOUT_MILLIS);
            FrameReader reader = new FrameReader(new BufferedInputStream(socket.getInputStream(), 65_536),
                    limits.maxLineBytes(), limits.maxBinaryBytes());
            FrameWriter out = new FrameWriter(socket.getOutputStream());
            out.send(WorkerProtocol.hello(registry.methods().keySet()));
            Frame place = reader.read();
            if (place == null) {
                return;
            }
            Refusal refusal = place(place);
            if (refusal != null) {
                out.send(WorkerProtocol.error(refusal.code(), refusal.message()));
                LOG.warn("refused method {} for {}: {}", methodId, peer, refusal.message());
                return;
            }
            out.send(WorkerProtocol.placed(methodId, hosted.inputNames(), hosted.outputNames()));
            socket.setSoTimeout(0);
            hosted.onOutput((output, sample) -> queue(WorkerProtocol.outputSample(output, sample)));
            hosted.start();
            LOG.info("running method {} for {}", methodId, peer);
            writer = Thread.ofVirtual().name("habla-worker-" + methodId + "-out").start(() -> writeLoop(out));
            readLoop(reader);
        } catch (IOException e) {
            LOG.info("connection of method {} from {} ended: {}", methodId, peer, e.getMessage());
        } catch (RuntimeException e) {
            LOG.warn("connection of method {} from {} failed: {}", methodId, peer, e.toString());
        } finally {
            open = false;
            if (writer != null) {
                writer.interrupt();
            }
            if (hosted != null) {
                hosted.close();
                LOG.info("method {} for {} stopped ({} output samples dropped)", methodId, peer, dropped.get());
            }
        }
    }

    /** Why a place line was refused: an error code and a sentence. */
    private record Refusal(String code, String message) {
    }

    /** Makes and keeps the method a place line asks for; returns why not when it cannot. */
    private Refusal place(Frame f) {
        if (!f.type().equals("place")) {
            return new Refusal("not_place", "expected a place line first, got type '" + f.type() + "'");
        }
        String type;
        Layer layer;
        try {
            methodId = WorkerProtocol.text(f, "method");
            type = WorkerProtocol.text(f, "methodType");
            layer = Layer.fromConfig(WorkerProtocol.text(f, "layer"));
        } catch (FrameException | IllegalArgumentException e) {
            return new Refusal("bad_place", String.valueOf(e.getMessage()));
        }
        MethodProvider<?> provider = registry.method(type).orElse(null);
        if (provider == null) {
            return new Refusal("unknown_type", "this worker cannot run method type '" + type + "'");
        }
        if (!provider.layers().contains(layer)) {
            return new Refusal("bad_place", "type '" + type + "' cannot be placed in the " + layer.configName() + " layer");
        }
        JsonNode params = f.header().get("params");
        Map<String, ChannelDescriptor> channels;
        Map<String, ChannelDescriptor> commandChannels;
        try {
            channels = WorkerProtocol.channels(f, "channels");
            commandChannels = WorkerProtocol.channels(f, "commandChannels");
        } catch (FrameException e) {
            return new Refusal("bad_place", e.getMessage());
        }
        try {
            Record bound = ParamsJson.read(params, provider.paramsType());
            HostedMethod h = new HostedMethod(methodId, type, make(provider, layer, bound), clock, backgroundPool);
            channels.forEach(h::bindChannel);
            commandChannels.forEach(h::bindCommandChannel);
            hosted = h;
            return null;
        } catch (ConfigException e) {
            return new Refusal("bad_params", e.errors().stream().map(ConfigError::toString)
                    .collect(Collectors.joining("; ")));
        } catch (RuntimeException | LinkageError e) {
            return new Refusal("cannot_make", "type '" + type + "' cannot be made here: " + e.getMessage());
        }
    }

    private static <P extends Record> Method make(MethodProvider<P> provider, Layer layer, Record params) {
        return provider.create(layer, provider.paramsType().cast(params));
    }

    private void readLoop(FrameReader reader) throws IOException {
        while (open) {
            Frame f;
            try {
                f = reader.read();
            } catch (FrameException e) {
                queue(Frame.of(WorkerProtocol.error(e.code(), e.getMessage())));
                if (e.fatal()) {
                    throw e;
                }
                continue;
            }
            if (f == null) {
                throw new IOException("the daemon closed the connection");
            }
            if (!f.type().equals("sample")) {
                queue(Frame.of(WorkerProtocol.error("unexpected", "a worker takes sample lines, not '" + f.type() + "'")));
                continue;
            }
            try {
                String input = WorkerProtocol.text(f, "input");
                Payload value = SampleCodec.value(f, hosted.inputKind(input));
                ObjectNode h = f.header();
                hosted.offer(input, new Sample(value, "daemon", h.path("seq").asLong(0), h.path("t").asLong(0),
                        h.path("stale").asBoolean(false)));
            } catch (FrameException e) {
                queue(Frame.of(WorkerProtocol.error(e.code(), e.getMessage())));
            } catch (IllegalArgumentException e) {
                queue(Frame.of(WorkerProtocol.error("unknown_input", e.getMessage())));
            }
        }
    }

    private void queue(Frame f) {
        if (!outbound.offer(f)) {
            dropped.incrementAndGet();
        }
    }

    private void writeLoop(FrameWriter out) {
        long nextBeat = System.nanoTime();
        try {
            while (open) {
                long now = System.nanoTime();
                if (now - nextBeat >= 0) {
                    out.write(WorkerProtocol.heartbeat(hosted.ready(), hosted.readiness()));
                    nextBeat = now + TimeUnit.MILLISECONDS.toNanos(WorkerProtocol.HEARTBEAT_MILLIS);
                }
                Frame f = outbound.poll(Math.max(1, nextBeat - now), TimeUnit.NANOSECONDS);
                while (f != null) {
                    out.write(f);
                    f = outbound.poll();
                }
                out.flush();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("writing to the daemon failed: {}", e.toString());
            try {
                socket.close();
            } catch (IOException ignored) {
                // the reader notices the closed socket
            }
        }
    }
}
