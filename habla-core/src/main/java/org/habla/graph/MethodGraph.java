package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.config.MethodConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The running form of a valid config: every method on its runner, every wire connected ({@link GraphWiring}), every
 * interface link keeping its robot connections, staleness ({@link GraphStaleness}), the motion watchdog and the
 * status. The config was checked by the loader, so building only fails on what cannot be known before (a provider
 * that throws). A graph on a recording is built the same way, its interfaces on recorded drivers, fed by
 * {@link #replay()}.
 *
 * <pre>
 *   interface ──reading──▶ [sensors &amp; actuators] ──▶ [processing] ──▶ [virtual] ──sample──▶ control socket
 *   interface ◀─command─── [sensors &amp; actuators] ◀── [processing] ◀── [virtual] ◀──value─── control socket
 * </pre>
 */
public final class MethodGraph implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(MethodGraph.class);
    private static final long STOP_WAIT_MILLIS = 2_000;

    private final HablaConfig config;
    private final GraphRun run;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final Map<String, MethodRunner> runners = new LinkedHashMap<>();
    private final Map<String, InterfaceLink> links = new LinkedHashMap<>();
    private final Map<String, RemotePlacement> placements;
    private final LinkStates linkStates = new LinkStates();
    private final List<ExposedMethod> exposed;
    private final WiredShapes shapes = new WiredShapes();
    private final GraphStaleness staleness;
    private final MotionWatchdog watchdog;
    private final long startedMicros;
    private AutoCloseable watchdogTicker;
    private AutoCloseable realtimeCarriers;
    private boolean started;
    private final GraphTap tap;

    /** @param run live interfaces, or a recording: what differs between the two ({@link GraphRun}) */
    private MethodGraph(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap, GraphRun run) {
        this.tap = tap;
        this.run = run;
        this.config = config;
        GraphTopology topology = new GraphTopology(config);
        this.clock = clock;
        this.startedMicros = clock.nowMicros();
        this.backgroundPool = BackgroundPool.create("habla-background-");
        RealtimeThreads.configured(); // a wrong priority stops the build, not a thread
        for (InterfaceConfig ic : config.interfaces()) {
            InterfaceLink link = new InterfaceLink(ic, run.driver(ic), clock, linkStates);
            InterfaceTap.attach(link, tap, clock);
            links.put(ic.id(), link);
        }
        this.watchdog = new MotionWatchdog(config.safety().watchdogMs(), clock, List.copyOf(links.values()));
        links.values().forEach(l -> l.watchdog(watchdog));
        ThreadPlan threads = ThreadPlan.of(config, registry);
        for (MethodConfig mc : config.methods()) {
            Method made = createMethod(registry, mc, config.methods().indexOf(mc));
            runners.put(mc.id(), new MethodRunner(mc.id(), mc.type(), made, clock, backgroundPool, run.work(), tap,
                    config.cycleInputs(mc.id()), threads.choice(mc.id())));
        }
        this.placements = RemotePlacement.placeAll(config, runners, linkStates);
        this.exposed = GraphWiring.wire(config, topology, runners, links, watchdog, tap, run::entry, shapes);
        this.staleness = new GraphStaleness(topology, runners, links, placements, exposed);
        linkStates.onChange(staleness::refresh);
        run.wired(runners, exposed, topology, watchdog);
    }

    /** Builds the graph of a checked config. Nothing runs until {@link #start()}. */
    public static MethodGraph build(HablaConfig config, PluginRegistry registry, EngineClock clock) {
        return build(config, registry, clock, GraphTap.NONE);
    }

    /** Hands an audit log's entry to the graph's tap (a recording). */
    public void audit(org.habla.security.AuditEntry entry) {
        tap.audit(entry);
    }

    /** Builds the graph with a tap that sees everything crossing its edges (for recording). */
    public static MethodGraph build(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap) {
        return new MethodGraph(config, registry, clock, tap, new LiveRun(registry));
    }

    /**
     * Builds the same graph on a recording: every interface runs on a {@link RecordedDriver} with the recorded
     * channels, through which {@link #replay()} feeds the readings and link changes; commands are absorbed —
     * counted and tapped, never written anywhere. Every input skips the samples {@code skips} says the recorded
     * run skipped.
     */
    public static MethodGraph replaying(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap,
            Map<String, List<ChannelDescriptor>> channels, RecordedSkips skips) {
        return new MethodGraph(config, registry, clock, tap, new RecordedRun(channels, skips));
    }

    /**
     * What a replay drives in this graph: recorded readings, link changes and periodic work in, where an event
     * can reach and whether the graph is idle out.
     *
     * @throws IllegalStateException if the graph runs live interfaces, not a recording
     */
    public GraphReplay replay() {
        return run.replay();
    }

    /**
     * Waits until every effect of what came in has been handled — no sample waiting or being handled, no turn
     * or background task under way; false if that took longer than {@code millis}. Only a graph that replays a
     * recording counts its work; a live one throws {@link IllegalStateException}.
     */
    public boolean awaitIdle(long millis) throws InterruptedException {
        return run.work().awaitIdle(millis);
    }

    /**
     * Every interface's channels as its driver describes them, in config order, without connecting to
     * anything (for a recording's header).
     */
    public static Map<String, List<ChannelDescriptor>> channels(HablaConfig config, PluginRegistry registry) {
        Map<String, List<ChannelDescriptor>> m = new LinkedHashMap<>();
        for (InterfaceConfig ic : config.interfaces()) {
            m.put(ic.id(), List.copyOf(LiveDriver.create(registry, ic).channels()));
        }
        return m;
    }

    /** Makes the method of {@code $.methods[index]}; a constructor's refusal names that path. */
    private static Method createMethod(PluginRegistry registry, MethodConfig mc, int index) {
        try {
            return MethodProvider.make(registry.method(mc.type()).orElseThrow(() ->
                    new IllegalStateException("no method type '" + mc.type() + "'")), mc.layer(), mc.params());
        } catch (RuntimeException | LinkageError e) {
            throw new MethodNotMadeException(index, mc, e);
        }
    }

    /** Starts every method, then every link, then the watchdog. */
    public synchronized void start() {
        if (started) {
            throw new IllegalStateException("the graph is already started");
        }
        started = true;
        staleness.markAll();
        realtimeCarriers = RealtimeThreads.raiseCarriersIfAsked();
        runners.values().forEach(MethodRunner::start);
        links.values().forEach(InterfaceLink::start);
        placements.values().forEach(RemotePlacement::start);
        watchdogTicker = clock.every(50_000, () -> {
            tap.periodic(GraphReplay.WATCHDOG_TASK, clock.nowMicros(), -1);
            watchdog.check();
        });
        LOG.info("graph of '{}' started: {} methods, {} interfaces, {} sockets", config.system(), runners.size(),
                links.size(), exposed.size());
    }

    /** An interface of the graph (for tests and benchmarks in this package). */
    InterfaceLink interfaceLink(String interfaceId) {
        return links.get(interfaceId);
    }

    /** The method object of a method (for tests in this package). */
    Method method(String methodId) {
        return runners.get(methodId).method();
    }

    /** The worker link of a placed method (for tests and benchmarks in this package). */
    RemotePlacement placement(String methodId) {
        return placements.get(methodId);
    }

    /** The exposed methods, in config order, each with its socket settings. */
    public List<ControlPoint> controlPoints() {
        return List.copyOf(exposed);
    }

    /** The socket settings of an exposed method's control point. */
    public org.habla.net.Expose exposeOf(ControlPoint point) {
        return ((ExposedMethod) point).expose();
    }

    /** Every method's outputs, in config order (method by method, each in declaration order). */
    public List<OutputInfo> outputs() {
        List<OutputInfo> all = new ArrayList<>();
        for (MethodRunner r : runners.values()) {
            for (Output<?> out : r.method().outputs()) {
                all.add(new OutputInfo(r.id(), out.name(), shapes.of(r.id(), out)));
            }
        }
        return all;
    }

    /**
     * Hands every sample any method emits to {@code watcher}, on the thread that emits it, after the method's
     * subscribers in the graph; the watcher must not block (a monitor keeps the newest few and returns).
     * Closing the handle stops it.
     */
    public AutoCloseable watchOutputs(java.util.function.Consumer<org.habla.sample.Sample> watcher) {
        List<Runnable> undo = new ArrayList<>();
        for (MethodRunner r : runners.values()) {
            for (Output<?> out : r.method().outputs()) {
                Producer port = r.port(out);
                port.subscribe(watcher);
                undo.add(() -> port.unsubscribe(watcher));
            }
        }
        return () -> undo.forEach(Runnable::run);
    }

    /** Stops every motion now and keeps motion commands out until a control client writes again. */
    public void stopActuators(String reason) {
        watchdog.trip(reason);
    }

    /** A snapshot for the status endpoint: link states and staleness as one consistent moment. */
    public ObjectNode status() {
        return linkStates.read(this::statusNow);
    }

    private ObjectNode statusNow() {
        long now = clock.nowMicros();
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("system", config.system());
        n.put("uptimeS", (now - startedMicros) / 1e6);
        n.set("watchdog", watchdog.status());
        links.values().stream().map(InterfaceLink::status).forEach(n.putArray("interfaces")::add);
        runners.values().stream().map(r -> r.status(now)).forEach(n.putArray("methods")::add);
        return n;
    }

    /** Stops the actuators first, then the links' reconnecting, then the methods. */
    @Override
    public synchronized void close() {
        if (!started) {
            backgroundPool.shutdownNow();
            return;
        }
        started = false;
        closeQuietly(watchdogTicker);
        links.values().forEach(InterfaceLink::stopMotionNow);
        placements.values().forEach(RemotePlacement::stop);
        runners.values().forEach(r -> r.stop(STOP_WAIT_MILLIS));
        links.values().forEach(InterfaceLink::stop);
        backgroundPool.shutdownNow();
        closeQuietly(realtimeCarriers);
        LOG.info("graph of '{}' stopped", config.system());
    }

    private static void closeQuietly(AutoCloseable c) {
        if (c != null) {
            try {
                c.close();
            } catch (Exception e) {
                LOG.debug("close: {}", e.toString());
            }
        }
    }
}
