package org.habla.replay;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.Source;
import org.habla.daemon.Daemon;
import org.habla.graph.GraphTap;
import org.habla.graph.RecordedSkips;
import org.habla.recording.Cut;
import org.habla.recording.RecordedEvent;
import org.habla.recording.Recorder;
import org.habla.recording.RecordingDamagedException;
import org.habla.recording.RecordingException;
import org.habla.recording.RecordingHeader;
import org.habla.recording.RecordingSource;
import org.habla.plugin.PluginRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a daemon on a recording instead of a robot. The recorded readings and link changes go into the same
 * interface channels, the recorded control writes into the same control inputs, and the recorded runs of
 * periodic work (method ticks, the watchdog) happen between the same events — at the recorded times scaled by
 * the speed, or as fast as possible. After every event the replay waits until the graph is idle, so each
 * method sees the same sequence of inputs as in the recorded run whatever the speed; what the exposed methods
 * emit and the commands the graph would send are compared with the recording. Commands go nowhere.
 */
public final class Replayer {

    private static final Logger LOG = LoggerFactory.getLogger(Replayer.class);
    /** How far ahead of the next reading a recorded tick may have been taken before that reading's effect. */
    static final long LOOKAHEAD_MICROS = 300_000;
    static final String TICK_PREFIX = "tick:";

    /**
     * How to replay.
     *
     * @param speed         how many times faster than recorded; 0 for as fast as possible
     * @param controlWrites whether to replay the recorded control writes (off: only live clients write)
     * @param settleMillis  the longest wait for the graph to go idle after an event
     */
    public record Options(double speed, boolean controlWrites, long settleMillis) {

        public static final Options AS_FAST_AS_POSSIBLE = new Options(0, true, 10_000);

        public Options {
            if (speed < 0 || !Double.isFinite(speed)) {
                throw new IllegalArgumentException("speed must be positive (or 0 for as fast as possible), was " + speed);
            }
        }
    }

    private final Path file;
    private final RecordingHeader header;
    private final HablaConfig config;
    private final PluginRegistry registry;
    private final boolean recordedTicks;
    private final Optional<Cut> cut;
    private final Map<String, Set<Long>> skips;

    private Replayer(Path file, RecordingHeader header, HablaConfig config, PluginRegistry registry,
            boolean recordedTicks, Optional<Cut> cut, Map<String, Set<Long>> skips) {
        this.skips = skips;
        this.file = file;
        this.header = header;
        this.config = config;
        this.registry = registry;
        this.recordedTicks = recordedTicks;
        this.cut = cut;
    }

    /**
     * Reads a recording through, and the config to replay it with: the recorded one, or {@code override}
     * (whose interfaces and channels must be those of the recording). A recording damaged before its end is
     * refused with a {@link RecordingDamagedException}; a torn end is not damage.
     */
    public static Replayer open(Path file, Optional<Path> override, PluginRegistry registry)
            throws IOException, RecordingException, ConfigException {
        return open(file, override, registry, false);
    }

    /**
     * As {@link #open(Path, Optional, PluginRegistry)}; with {@code salvage}, a damaged recording is replayed up to
     * its damage instead of refused.
     */
    public static Replayer open(Path file, Optional<Path> override, PluginRegistry registry, boolean salvage)
            throws IOException, RecordingException, ConfigException {
        RecordingHeader header;
        boolean ticks = false;
        Optional<Cut> cut;
        Map<String, Set<Long>> skips = new HashMap<>();
        try (RecordingSource r = RecordingSource.open(file)) {
            header = r.header();
            for (RecordedEvent e = r.next(); e != null; e = r.next()) {
                ticks |= e instanceof RecordedEvent.Tick;
                if (e instanceof RecordedEvent.Skip s) {
                    // known before the replay starts: a skip is recorded after the sample it skips was offered
                    skips.computeIfAbsent(inputKey(s.method(), s.input()), k -> new HashSet<>()).add(s.arrival());
                }
            }
            cut = r.cut();
        }
        if (cut.isPresent() && cut.get().damage() && !salvage) {
            throw new RecordingDamagedException(cut.get());
        }
        ConfigLoader loader = new ConfigLoader(registry);
        HablaConfig config = override.isPresent() ? loader.load(override.get())
                : loader.parse(header.config().toString(),
                        header.configDir().isEmpty() ? Path.of("").toAbsolutePath() : Path.of(header.configDir()));
        for (var ic : config.interfaces()) {
            if (!header.interfaces().containsKey(ic.id())) {
                throw new RecordingException("interface '" + ic.id() + "' of the config is not in the recording "
                        + "(it has " + header.interfaces().keySet() + ")");
            }
        }
        for (var mc : config.methods()) {
            for (var e : mc.inputs().entrySet()) {
                if (e.getValue() instanceof Source.Channel ch && header.interfaces().get(ch.interfaceId()).stream()
                        .noneMatch(c -> c.name().equals(ch.channel())) && !ch.channel().equals("link")) {
                    throw new RecordingException("method '" + mc.id() + "' reads @" + ch.interfaceId() + "."
                            + ch.channel() + ", which the recording does not have");
                }
            }
        }
        return new Replayer(file, header, config, registry, ticks, cut, skips);
    }

    /** The key of one method's input in the map of recorded skips. */
    private static String inputKey(String method, String input) {
        return method + "." + input;
    }

    /** Where the recording stops being readable, if it does: a torn end, or damage being salvaged. */
    public Optional<Cut> cut() {
        return cut;
    }

    public HablaConfig config() {
        return config;
    }

    public RecordingHeader header() {
        return header;
    }

    /**
     * Replays the whole recording and stops the daemon.
     *
     * @param recordTo  a new file to record the replay to, if wanted
     * @param onStarted called once the daemon's sockets are up, before the first event
     */
    public ReplayResult run(Options options, Optional<Path> recordTo, Consumer<Daemon> onStarted)
            throws IOException, RecordingException, InterruptedException {
        ReplayClock clock = new ReplayClock(header.startMicros());
        Daemon.checkPorts(config);
        Recorder recorder = null;
        if (recordTo.isPresent()) {
            recorder = Recorder.create(recordTo.get(), new RecordingHeader(header.startMicros(), header.timeScale(),
                    header.config(), header.configDir(), header.interfaces()), clock);
        }
        OutputComparison comparison = new OutputComparison(recorder == null ? GraphTap.NONE : recorder);
        RecordedSkips recordedSkips = (method, input, arrival) ->
                skips.getOrDefault(inputKey(method, input), Set.of()).contains(arrival);
        Daemon daemon = Daemon.replaying(config, registry, clock, comparison, header.interfaces(), recordedSkips);
        try (RecordingSource reader = RecordingSource.open(file)) {
            onStarted.accept(daemon);
            ReplayFeed feed = new ReplayFeed(daemon.graph(), clock, options, recordedTicks, header.startMicros());
            long wallStart = System.nanoTime();
            Deque<RecordedEvent> ahead = new ArrayDeque<>();
            boolean more = true;
            while (true) {
                while (more && (ahead.isEmpty() || ahead.peekLast().t() - ahead.peekFirst().t() < LOOKAHEAD_MICROS)) {
                    RecordedEvent next = reader.next();
                    if (next == null) {
                        more = false;
                    } else {
                        ahead.addLast(next);
                    }
                }
                RecordedEvent e = ahead.pollFirst();
                if (e == null) {
                    break;
                }
                if (e instanceof RecordedEvent.Reading r) {
                    feed.ticksTakenBefore(r.t(), m -> daemon.graph().replay().reaches(r.iface(), m), ahead);
                } else if (e instanceof RecordedEvent.ControlWrite w && options.controlWrites()) {
                    feed.ticksTakenBefore(w.t(), m -> daemon.graph().replay().reachesFromControl(w.socket(), m), ahead);
                }
                feed.event(e, comparison);
            }
            feed.settle();
            long wallMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - wallStart);
            return new ReplayResult(feed.readings, feed.controlWrites, feed.rejected, feed.ticks, feed.unsettled,
                    Math.max(0, feed.lastMicros - header.startMicros()), wallMillis, comparison.matches(),
                    reader.cut(), feed.complete, feed.recordedDrops);
        } finally {
            daemon.close();
            if (recorder != null) {
                recorder.close();
            }
        }
    }
}
