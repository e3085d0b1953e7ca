package org.habla.graph;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.habla.config.ChannelRef;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Reconnect;
import org.habla.config.Source;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Input;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The running form of a valid config: every method on its runner, every wire connected, every
 * interface link keeping its robot connections, and the motion watchdog. The config was checked
 * by the loader, so building only fails on what cannot be known before (a provider that throws).
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
    private final GraphTopology topology;
    private final GraphReplay replay;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final Map<String, MethodRunner> runners = new LinkedHashMap<>();
    private final Map<String, InterfaceLink> links = new LinkedHashMap<>();
    private final Map<String, Set<String>> upstreamInterfaces = new HashMap<>();
    private final Map<String, Set<Source.Channel>> upstreamChannels = new HashMap<>();
    private final Map<String, RemotePlacement> placements = new LinkedHashMap<>();
    private final Map<String, Set<String>> upstreamPlacements = new HashMap<>();
    private final LinkStates linkStates = new LinkStates();
    private final List<ExposedMethod> exposed = new ArrayList<>();
    private final MotionWatchdog watchdog;
    private final long startedMicros;
    private AutoCloseable watchdogTicker;
    private boolean started;

    private final GraphTap tap;
    private final WorkCount work;
    private final boolean replayed;

    private MethodGraph(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap,
            Map<String, List<ChannelDescriptor>> recordedChannels) {
        this.tap = tap;
        this.replayed = recordedChannels != null;
        this.work = replayed ? new WorkCount() : WorkCount.NONE;
        this.config = config;
        this.topology = new GraphTopology(config);
        this.clock = clock;
        this.startedMicros = clock.nowMicros();
        AtomicInteger n = new AtomicInteger();
        this.backgroundPool = Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()),
                r -> {
                    Thread t = new Thread(r, "habla-background-" + n.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        for (InterfaceConfig ic : config.interfaces()) {
            org.habla.driver.Driver driver = replayed ? new RecordedDriver(recordedChannels.getOrDefault(ic.id(), List.of()))
                    : createDriver(registry, ic);
            links.put(ic.id(), new InterfaceLink(ic, driver, clock, tap, replayed, linkStates));
        }
        this.watchdog = new MotionWatchdog(config.safety().watchdogMs(), clock, List.copyOf(links.values()));
        this.replay = new GraphReplay(links, runners, upstreamInterfaces, exposed, topology, watchdog, work);
        links.values().forEach(l -> l.watchdog(watchdog));
        for (MethodConfig mc : config.methods()) {
            runners.put(mc.id(), new MethodRunner(mc.id(), mc.type(), createMethod(registry, mc), clock, backgroundPool,
                    work, tap, config.cycleInputs(mc.id())));
        }
        var workerLink = config.methods().stream().anyMatch(m -> m.host().isPresent())
                ? config.security().workerLink() : org.habla.security.WorkerLink.PLAIN;
        for (MethodConfig mc : config.methods()) {
            if (mc.host().isPresent()) {
                MethodRunner runner = runners.get(mc.id());
                RemotePlacement p = new RemotePlacement(mc, runner, config.limits(), Reconnect.DEFAULTS, linkStates,
                        workerLink);
                runner.placeOn(p);
                placements.put(mc.id(), p);
            }
        }
        for (MethodConfig mc : config.methods()) {
            wire(mc);
        }
        routeNotices();
        for (String id : motionPath()) {
            runners.get(id).followMotionResets(watchdog::resets);
        }
        for (MethodConfig mc : config.methods()) {
            upstreamInterfaces.put(mc.id(), topology.upstreamInterfaces(mc.id()));
            upstreamChannels.put(mc.id(), topology.upstreamChannels(mc.id()));
            Set<String> placedUpstream = new LinkedHashSet<>(topology.feeding(mc.id()));
            placedUpstream.retainAll(placements.keySet());
            upstreamPlacements.put(mc.id(), placedUpstream);
        }
        linkStates.onChange(this::refreshStale);
    }

    /** Builds the graph of a checked config. Nothing runs until {@link #start()}. */
    public static MethodGraph build(HablaConfig config, PluginRegistry registry, EngineClock clock) {
        return new MethodGraph(config, registry, clock, GraphTap.NONE, null);
    }

    /** Hands an audit log's entry to the graph's tap (a recording). */
    public void audit(org.habla.security.AuditEntry entry) {
        tap.audit(entry);
    }

    /** Builds the graph with a tap that sees everything crossing its edges (for recording). */
    public static MethodGraph build(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap) {
        return new MethodGraph(config, registry, clock, tap, null);
    }

    /**
     * Builds a graph that replays a recording: every interface has the recorded channels but no connection;
     * readings and link changes come in through {@link #replay()}, and commands
     * are absorbed — counted and tapped, never written anywhere.
     */
    public static MethodGraph replaying(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap,
            Map<String, List<ChannelDescriptor>> channels) {
        return new MethodGraph(config, registry, clock, tap, Map.copyOf(channels));
    }

    /**
     * What a replay drives in this graph: recorded readings, link changes and periodic work in, where an event
     * can reach and whether the graph is idle out.
     *
     * @throws IllegalStateException if the graph runs live interfaces, not a recording
     */
    public GraphReplay replay() {
        if (!replayed) {
            throw new IllegalStateException("this graph runs live interfaces, not a recording");
        }
        return replay;
    }

    /**
     * Waits until every effect of what came in has been handled — no sample waiting or being handled, no turn
     * or background task under way; false if that took longer than {@code millis}. Only a graph that replays a
     * recording counts its work; a live one throws {@link IllegalStateException}.
     */
    public boolean awaitIdle(long millis) throws InterruptedException {
        return work.awaitIdle(millis);
    }

    /**
     * Every interface's channels as its driver describes them, in config order, without connecting to
     * anything (for a recording's header).
     */
    public static Map<String, List<ChannelDescriptor>> channels(HablaConfig config, PluginRegistry registry) {
        Map<String, List<ChannelDescriptor>> m = new LinkedHashMap<>();
        for (InterfaceConfig ic : config.interfaces()) {
            m.put(ic.id(), List.copyOf(createDriver(registry, ic).channels()));
        }
        return m;
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static org.habla.driver.Driver createDriver(PluginRegistry registry, InterfaceConfig ic) {
        DriverProvider provider = registry.driver(ic.driver()).orElseThrow(() ->
                new IllegalStateException("no driver type '" + ic.driver() + "'"));
        return provider.create(ic.address(), ic.params());
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Method createMethod(PluginRegistry registry, MethodConfig mc) {
        MethodProvider provider = registry.method(mc.type()).orElseThrow(() ->
                new IllegalStateException("no method type '" + mc.type() + "'"));
        return provider.create(mc.layer(), mc.params());
    }

    private void wire(MethodConfig mc) {
        MethodRunner runner = runners.get(mc.id());
        Map<String, Source> controlSources = new HashMap<>();
        for (Map.Entry<String, Source> e : mc.inputs().entrySet()) {
            Input<?> input = runner.method().input(e.getKey()).orElseThrow();
            InputSlot slot = runner.slot(input);
            switch (e.getValue()) {
                case Source.MethodOutput mo -> {
                    MethodRunner from = runners.get(mo.methodId());
                    Output<?> out = from.method().output(mo.output()).orElseThrow();
                    from.port(out).subscribe(slot::offer);
                }
                case Source.Channel ch -> {
                    InterfaceLink link = links.get(ch.interfaceId());
                    link.reading(ch.channel()).subscribe(slot::offer);
                    runner.bindChannel(input, link.channel(ch.channel()));
                }
                case Source.Control c -> controlSources.put(e.getKey(), c);
            }
        }
        for (Map.Entry<String, ChannelRef> e : mc.commands().entrySet()) {
            Output<?> out = runner.method().output(e.getKey()).orElseThrow();
            InterfaceLink link = links.get(e.getValue().interfaceId());
            String channel = e.getValue().channel();
            ChannelDescriptor descriptor = link.channel(channel);
            if (descriptor != null) {
                runner.bindCommandChannel(out, descriptor);
            }
            runner.port(out).subscribe(sample -> link.command(channel, sample));
        }
        mc.expose().ifPresent(x -> exposed.add(new ExposedMethod(runner,
                x, ExposedMethod.controlInputsOf(runner, controlSources), watchdog, tap, topology.actuates(mc.id()))));
    }

    /** Sends what each method tells control clients to the sockets whose values reach it. */
    private void routeNotices() {
        for (MethodRunner r : runners.values()) {
            List<ExposedMethod> told = exposed.stream().filter(x -> !x.controlInputs().isEmpty()
                    && topology.downstream(x.methodId()).contains(r.id())).toList();
            if (!told.isEmpty()) {
                r.tellControlVia(notice -> told.forEach(x -> x.notice(notice)));
            }
        }
    }

    /**
     * The methods whose outputs lead, through other methods or directly, to a motion command channel: the ones
     * that must forget their motion when the watchdog stops the robot.
     */
    private Set<String> motionPath() {
        Set<String> found = new LinkedHashSet<>();
        for (MethodConfig mc : config.methods()) {
            boolean drives = mc.commands().values().stream().anyMatch(ref -> {
                ChannelDescriptor d = links.get(ref.interfaceId()).channel(ref.channel());
                return d != null && d.motion();
            });
            if (drives) {
                topology.feeding(mc.id(), found);
            }
        }
        return found;
    }

    /**
     * Marks stale every method that depends on an interface that is down or on a worker that is lost
     * without a local fallback, and fresh again the others. Runs under the link-state lock, as part of the
     * change that caused it.
     */
    private void refreshStale() {
        for (MethodRunner r : runners.values()) {
            String why = staleness(r.id());
            boolean stale = why != null;
            if (r.stale() != stale) {
                r.stale(stale);
                for (ExposedMethod x : exposed) {
                    if (x.methodId().equals(r.id())) {
                        x.staleChanged(stale, stale ? why : "all links up");
                    }
                }
            }
        }
    }

    /** Why a method's outputs are stale now, or null. */
    private String staleness(String methodId) {
        for (String id : upstreamInterfaces.getOrDefault(methodId, Set.of())) {
            if (!links.get(id).up()) {
                return "interface " + id + " is down";
            }
        }
        for (Source.Channel ch : upstreamChannels.getOrDefault(methodId, Set.of())) {
            String why = links.get(ch.interfaceId()).unavailable(ch.channel());
            if (why != null) {
                return "the device of @" + ch.interfaceId() + "." + ch.channel() + " is unavailable: " + why;
            }
        }
        for (String id : upstreamPlacements.getOrDefault(methodId, Set.of())) {
            RemotePlacement p = placements.get(id);
            if (!p.healthy()) {
                return "worker " + p.host() + " of method " + id + " is lost";
            }
        }
        return null;
    }

    /** Starts every method, then every link, then the watchdog. */
    public synchronized void start() {
        if (started) {
            throw new IllegalStateException("the graph is already started");
        }
        started = true;
        // Until a link reports up, what depends on it is stale.
        for (MethodRunner r : runners.values()) {
            r.stale(staleness(r.id()) != null);
        }
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
    public org.habla.config.Expose exposeOf(ControlPoint point) {
        return ((ExposedMethod) point).expose();
    }

    /** Every method's outputs, in config order (method by method, each in declaration order). */
    public List<OutputInfo> outputs() {
        List<OutputInfo> all = new ArrayList<>();
        for (MethodRunner r : runners.values()) {
            for (Output<?> out : r.method().outputs()) {
                all.add(new OutputInfo(r.id(), out.name(), out.shape()));
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
                OutputPort port = r.port(out);
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
        ObjectNode w = n.putObject("watchdog");
        w.put("timeoutMs", watchdog.timeoutMillis());
        w.put("tripped", watchdog.tripped());
        w.put("trips", watchdog.trips());
        if (!watchdog.lastReason().isEmpty()) {
            w.put("lastReason", watchdog.lastReason());
        }
        ArrayNode ifs = n.putArray("interfaces");
        links.values().forEach(l -> ifs.add(l.status()));
        ArrayNode ms = n.putArray("methods");
        runners.values().forEach(r -> ms.add(r.status(now)));
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
