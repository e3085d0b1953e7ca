package org.habla.method;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/**
 * Runs one method in memory, without sockets, threads or an engine: push samples into its inputs,
 * step its clock, read what it emitted. Shipped in the main sources so method authors test with it.
 *
 * <pre>{@code
 * MethodHarness h = MethodHarness.started("near", new Threshold(ParamsJson.defaults(ThresholdParams.class)));
 * h.push("nearest", RecordValue.builder().put("distanceM", 1.0).build());
 * h.push("nearest", RecordValue.builder().put("distanceM", 0.4).build());
 * assertThat(h.values("label")).containsExactly(new TextValue("far"), new TextValue("near"));
 * }</pre>
 *
 * Background work runs when {@link #runBackground()} is called (or at once with
 * {@link #runBackgroundAtOnce()}), so tests decide when slow work finishes.
 *
 * <p>A method that throws from a hook is put in {@code FAILED}, as the engine would; the harness call that made
 * it fail ({@link #start}, {@link #push}, {@link #advanceMillis}, {@link #runBackground}, ...) then throws an
 * {@link AssertionError} with the method's exception as its cause, so a test never passes over a failure it did
 * not ask for. A test about a failure says so first with {@link #expectFailure()} and then reads {@link #state()}
 * and {@link #failure()}.
 */
public final class MethodHarness {

    private final Method method;
    private MethodLifecycle lifecycle;
    private final String id;
    private final Map<String, List<Sample>> emitted = new HashMap<>();
    private final Map<String, ChannelDescriptor> channels = new HashMap<>();
    private final Map<String, ChannelDescriptor> commandChannels = new HashMap<>();
    private final HarnessBackground background = new HarnessBackground();
    private final List<ControlNotice> notices = new ArrayList<>();
    private final Map<String, Long> sequences = new HashMap<>();
    private long nowMicros = 1_700_000_000_000_000L;
    private long nextTickMicros;
    private boolean ready = true;
    private boolean stale;
    private boolean failureExpected;
    private String readinessDetail = "";

    private MethodHarness(String id, Method method) {
        this.id = id;
        this.method = method;
    }

    /** Attaches {@code method} under {@code id}; call {@link #start()} next (or use {@link #started}). */
    public static MethodHarness of(String id, Method method) {
        MethodHarness h = new MethodHarness(id, method);
        h.lifecycle = MethodLifecycle.attach(method, h.new Context());
        return h;
    }

    /** Attaches and starts {@code method}. */
    public static MethodHarness started(String id, Method method) {
        return of(id, method).start();
    }

    /** Describes the interface channel an input is wired to (before {@link #start()}). */
    public MethodHarness wireChannel(String input, ChannelDescriptor channel) {
        requireInput(input);
        channels.put(input, channel);
        return this;
    }

    /** Describes the interface command channel an output writes (before {@link #start()}). */
    public MethodHarness wireCommand(String output, ChannelDescriptor channel) {
        requireOutput(output);
        commandChannels.put(output, channel);
        return this;
    }

    public MethodHarness start() {
        lifecycle.start();
        method.tickPeriod().ifPresent(p -> nextTickMicros = nowMicros + p.toNanos() / 1000);
        return failedUnlessExpected();
    }

    /**
     * Lets the method fail: from now on a hook that throws leaves the method {@code FAILED} (read {@link #state()}
     * and {@link #failure()}) instead of failing the test. Call it before the call expected to fail (before
     * {@link #start()} for a start that fails: {@code MethodHarness.of(id, m).expectFailure().start()}).
     */
    public MethodHarness expectFailure() {
        failureExpected = true;
        return this;
    }

    /** Why the method failed ({@code "failed to handle a sample of in: java.lang..."}), or an empty string. */
    public String failure() {
        return lifecycle.failure();
    }

    /** Makes background work run as soon as it is asked for. */
    public MethodHarness runBackgroundAtOnce() {
        background.runAtOnceFromNowOn();
        return failedUnlessExpected();
    }

    /** Runs the background work asked for so far; returns how many tasks ran. */
    public int runBackground() {
        int n = background.runAll();
        failedUnlessExpected();
        return n;
    }

    /** Hands a value to an input, stamped now. */
    public MethodHarness push(String input, Payload value) {
        return push(input, value, nowMicros);
    }

    /** Hands a value to an input with an explicit source time. */
    public MethodHarness push(String input, Payload value, long sourceMicros) {
        Input<?> in = requireInput(input);
        if (!in.accepts(value)) {
            throw new IllegalArgumentException(in + " does not accept " + value.kind().wireName());
        }
        long seq = sequences.merge("in:" + input, 1L, Long::sum);
        lifecycle.deliver(in, new Sample(value, "harness." + input, seq, sourceMicros, false));
        return failedUnlessExpected();
    }

    /**
     * Writes a value to an input as a control client would: a value the input's check refuses throws
     * {@link IllegalArgumentException} with the message the client would get, and is not delivered.
     */
    public MethodHarness write(String input, Payload value) {
        Input<?> in = requireInput(input);
        in.refusal(value).ifPresent(why -> {
            throw new IllegalArgumentException(why);
        });
        return push(input, value);
    }

    /** Makes the method stale or fresh, as a link or device its inputs come from going down or up would. */
    public MethodHarness stale(boolean isStale) {
        stale = isStale;
        return this;
    }

    /** Tells the method the engine stopped the robot (the motion watchdog tripped, or control came back). */
    public MethodHarness motionStopped() {
        lifecycle.motionStopped();
        return failedUnlessExpected();
    }

    /** Moves the clock forward, running every tick that falls due on the way. */
    public MethodHarness advanceMillis(long millis) {
        long target = nowMicros + millis * 1000;
        Optional<java.time.Duration> period = method.tickPeriod();
        if (period.isPresent()) {
            long step = period.get().toNanos() / 1000;
            while (nextTickMicros <= target) {
                nowMicros = nextTickMicros;
                lifecycle.tick(nowMicros);
                nextTickMicros += step;
            }
        }
        nowMicros = target;
        return failedUnlessExpected();
    }

    public long nowMicros() {
        return nowMicros;
    }

    /** Every sample emitted on {@code output}, oldest first. */
    public List<Sample> samples(String output) {
        requireOutput(output);
        return List.copyOf(emitted.getOrDefault(output, List.of()));
    }

    /** Every payload emitted on {@code output}, oldest first. */
    public List<Payload> values(String output) {
        return samples(output).stream().map(Sample::payload).toList();
    }

    /** The last payload emitted on {@code output}; fails if there is none. */
    public Payload last(String output) {
        List<Sample> s = samples(output);
        if (s.isEmpty()) {
            throw new AssertionError(id + " emitted nothing on " + output);
        }
        return s.get(s.size() - 1).payload();
    }

    /** Every notice the method told control clients, oldest first. */
    public List<ControlNotice> notices() {
        return List.copyOf(notices);
    }

    /** Forgets what was emitted and told so far. */
    public MethodHarness clear() {
        emitted.clear();
        notices.clear();
        return this;
    }

    public MethodState state() {
        return lifecycle.state();
    }

    public boolean ready() {
        return ready;
    }

    public String readinessDetail() {
        return readinessDetail;
    }

    public MethodHarness stop() {
        lifecycle.stop();
        return this;
    }

    /** Fails the test if the method failed and the test did not say it expects that. */
    private MethodHarness failedUnlessExpected() {
        if (!failureExpected && lifecycle.state() == MethodState.FAILED) {
            throw new AssertionError("method " + id + " (" + method.getClass().getSimpleName() + ") "
                    + lifecycle.failure() + "; call expectFailure() first if the test expects it",
                    lifecycle.failureCause());
        }
        return this;
    }

    private Input<?> requireInput(String name) {
        return method.input(name).orElseThrow(() -> new IllegalArgumentException(
                id + " has no input '" + name + "'; it has " + method.inputs().stream().map(Input::name).toList()));
    }

    private void requireOutput(String name) {
        method.output(name).orElseThrow(() -> new IllegalArgumentException(
                id + " has no output '" + name + "'; it has " + method.outputs().stream().map(Output::name).toList()));
    }

    private final class Context implements MethodContext {
        @Override
        public String methodId() {
            return id;
        }

        @Override
        public long nowMicros() {
            return nowMicros;
        }

        @Override
        public boolean stale() {
            return stale;
        }

        @Override
        public void emit(Output<?> output, Payload value, long sourceMicros) {
            if (!output.type().isInstance(value)) {
                throw new IllegalArgumentException(output + " cannot carry " + value.kind().wireName());
            }
            long seq = sequences.merge(output.name(), 1L, Long::sum);
            emitted.computeIfAbsent(output.name(), k -> new ArrayList<>())
                    .add(new Sample(value, id + "." + output.name(), seq, sourceMicros, stale));
        }

        @Override
        public Optional<ChannelDescriptor> channelOf(Input<?> input) {
            return Optional.ofNullable(channels.get(input.name()));
        }

        @Override
        public void tellControl(ControlNotice notice) {
            notices.add(notice);
        }

        @Override
        public Optional<ChannelDescriptor> commandChannelOf(Output<?> output) {
            return Optional.ofNullable(commandChannels.get(output.name()));
        }

        @Override
        public void readiness(boolean isReady, String detail) {
            ready = isReady;
            readinessDetail = detail;
        }

        @Override
        public <T> void background(String what, Callable<T> task, Consumer<T> done) {
            background.submit(lifecycle, what, task, done);
        }
    }
}
