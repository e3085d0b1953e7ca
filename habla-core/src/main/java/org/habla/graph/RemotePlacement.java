package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.config.Fallback;
import org.habla.config.HablaConfig;
import org.habla.net.Limits;
import org.habla.config.MethodConfig;
import org.habla.config.Reconnect;
import org.habla.method.Input;
import org.habla.net.Frame;
import org.habla.net.WorkerProtocol;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The daemon's side of a method placed on a worker ({@code "host"} in the config): keeps one TCP
 * connection to the worker, has it make the method from its type and params, sends it the samples the
 * method's runner takes from its input slots and publishes what comes back on the method's own output
 * ports, so the rest of the graph cannot tell where the method runs.
 *
 * <p>Nothing here blocks the graph: samples wait in a bounded queue for the writer thread and are dropped
 * (counted) when it is full or while the worker is lost. A worker that closes the connection or stays
 * silent longer than {@link #LOST_AFTER_MILLIS} (it sends a heartbeat every second) is lost: the placement
 * reports down, the runner falls back to the local method if the config asks for it, and the connection
 * is tried again with a doubling wait.
 */
final class RemotePlacement {

    private static final Logger LOG = LoggerFactory.getLogger(RemotePlacement.class);
    /** Samples waiting for the worker connection; more are dropped and counted. */
    static final int QUEUE_SAMPLES = 256;
    /** Silence after which a worker is declared lost (three missed heartbeats). */
    static final long LOST_AFTER_MILLIS = 3 * WorkerProtocol.HEARTBEAT_MILLIS;

    // Package-private where the connection (PlacementSession) reads or counts them.
    final MethodConfig config;
    final String host;
    final int port;
    final MethodRunner runner;
    final Limits limits;
    final Reconnect reconnect;
    final org.habla.security.WorkerLink link;
    private final LinkStates states;
    final ReconnectingLink<PlacementSession> connection;
    final ArrayBlockingQueue<Frame> outbound = new ArrayBlockingQueue<>(QUEUE_SAMPLES);
    final AtomicLong sent = new AtomicLong();
    final AtomicLong received = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    final AtomicLong badLines = new AtomicLong();

    RemotePlacement(MethodConfig config, MethodRunner runner, Limits limits, Reconnect reconnect, LinkStates states) {
        this(config, runner, limits, reconnect, states, org.habla.security.WorkerLink.PLAIN);
    }

    /** @param link the secret the daemon proves to the worker, and the TLS it speaks to it */
    RemotePlacement(MethodConfig config, MethodRunner runner, Limits limits, Reconnect reconnect, LinkStates states,
            org.habla.security.WorkerLink link) {
        this.link = link;
        this.config = config;
        String text = config.host().orElseThrow();
        int colon = text.lastIndexOf(':');
        String h = text.substring(0, colon);
        this.host = h.startsWith("[") && h.endsWith("]") ? h.substring(1, h.length() - 1) : h;
        this.port = Integer.parseInt(text.substring(colon + 1));
        this.runner = runner;
        this.limits = limits;
        this.reconnect = reconnect;
        this.states = states;
        this.connection = new ReconnectingLink<>("habla-worker-link-" + config.id(), reconnect, () -> new PlacementSession(this),
                new OutageLog(LOG, "worker " + config.host().orElseThrow() + " of method " + config.id()),
                new ReconnectingLink.StateListener() {
                    @Override
                    public void flip(boolean nowUp, boolean wasUp, Runnable flip) {
                        if (!nowUp && !fallsBackToLocal()) {
                            // Before the placement reads down: whoever sees it down or the method stale sees why.
                            runner.context().readiness(false, "worker " + host() + " is lost");
                        }
                        flipUnderStates(nowUp, wasUp, flip);
                    }

                    @Override
                    public void wentDown(boolean wasUp) {
                        lost();
                    }
                });
    }

    /** The worker as the config names it ({@code host:port}). */
    String host() {
        return config.host().orElseThrow();
    }

    /**
     * Places every method of {@code config} that names a worker ({@code "host"}) on it: each gets a placement, its
     * runner hands its samples to the worker from now on ({@link MethodHost.OnWorker}), and a method without a local
     * fallback is not ready until its worker takes it. The worker link's security is read only when a method is
     * placed. Nothing connects until {@link #start}.
     *
     * @return the placements, by method id, in config order
     */
    static Map<String, RemotePlacement> placeAll(HablaConfig config, Map<String, MethodRunner> runners,
            LinkStates states) {
        Map<String, RemotePlacement> placed = new LinkedHashMap<>();
        org.habla.security.WorkerLink link = null;
        for (MethodConfig mc : config.methods()) {
            if (mc.host().isEmpty()) {
                continue;
            }
            if (link == null) {
                link = config.security().workerLink();
            }
            MethodRunner runner = runners.get(mc.id());
            RemotePlacement p = new RemotePlacement(mc, runner, config.limits(), Reconnect.DEFAULTS, states, link);
            runner.runOn(new MethodHost.OnWorker(mc.id(), p, runner.local()));
            if (!p.fallsBackToLocal()) {
                runner.context().startNotReady("waiting for worker " + p.host());
            }
            placed.put(mc.id(), p);
        }
        return placed;
    }

    /** Whether the worker runs the method now. */
    boolean up() {
        return connection.up();
    }

    /** Whether the method runs in the daemon while the worker is lost. */
    boolean fallsBackToLocal() {
        return config.fallback() == Fallback.LOCAL;
    }

    /** Whether the method's outputs are being produced, here or there. */
    boolean healthy() {
        return connection.up() || fallsBackToLocal();
    }

    void start() {
        connection.start();
    }

    void stop() {
        connection.stop();
    }

    /** Queues a sample for the worker; never blocks. From the method's runner thread. */
    void forward(Input<?> input, Sample sample) {
        if (!outbound.offer(WorkerProtocol.inputSample(input.name(), sample))) {
            dropped.incrementAndGet();
        }
    }

    /** Counts a sample that had nowhere to go: the worker is lost and there is no local fallback. */
    void dropWhileLost() {
        dropped.incrementAndGet();
    }

    /** The wait chooser of this link (tests and benchmarks observe the waits it chooses). */
    BackOff backOff() {
        return connection.backOff();
    }

    /** Makes the placement up or down under the link-state lock, and brings staleness up to date with it. */
    private void flipUnderStates(boolean nowUp, boolean wasUp, Runnable flip) {
        states.locked(() -> {
            flip.run();
            if (nowUp || wasUp || connection.connects() == 0 && connection.failures() == 1) {
                states.refreshStaleness();
            }
        });
    }

    /**
     * The worker is lost (or never came): nothing waits for it, and the method runs here if the config says so
     * (without a fallback the method was marked not ready as the placement went down).
     */
    private void lost() {
        outbound.clear();
        if (fallsBackToLocal() && connection.running()) {
            // On the method's thread, between its messages: the daemon's copy starts there.
            runner.turn(() -> {
                if (runner.host() instanceof MethodHost.OnWorker w) {
                    w.fallBack();
                }
            });
        }
    }

    ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("host", host());
        n.put("up", connection.up());
        n.put("fallback", config.fallback().configName());
        n.put("connects", connection.connects());
        n.put("failures", connection.failures());
        n.put("sent", sent.get());
        n.put("received", received.get());
        n.put("dropped", dropped.get());
        n.put("badLines", badLines.get());
        if (!connection.lastError().isEmpty()) {
            n.put("lastError", connection.lastError());
        }
        return n;
    }
}
