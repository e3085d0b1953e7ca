package org.habla.replay;

import java.util.Deque;
import java.util.HashSet;
import java.util.Iterator;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.habla.graph.MethodGraph;
import org.habla.method.Input;
import org.habla.net.ControlPoint;
import org.habla.recording.RecordedEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What a {@link Replayer}'s thread does with each recorded event: paces it to the recorded time (at the
 * options' speed), feeds it to the replaying graph — readings, link changes, control writes, recorded ticks —
 * or hands it to the comparison, waits for the graph to settle, and counts what it did.
 */
final class ReplayFeed {

    private static final Logger LOG = LoggerFactory.getLogger(Replayer.class);

    private final MethodGraph graph;
    private final ReplayClock clock;
    private final Replayer.Options options;
    private final boolean recordedTicks;
    private final long wallStartNanos = System.nanoTime();
    private final long startMicros;
    long readings;
    long controlWrites;
    long rejected;
    long ticks;
    long unsettled;
    long recordedDrops;
    long lastMicros;
    boolean complete;

    ReplayFeed(MethodGraph graph, ReplayClock clock, Replayer.Options options, boolean recordedTicks, long startMicros) {
        this.graph = graph;
        this.startMicros = startMicros;
        this.lastMicros = startMicros;
        this.clock = clock;
        this.options = options;
        this.recordedTicks = recordedTicks;
    }

    void event(RecordedEvent e, OutputComparison comparison) throws InterruptedException {
        switch (e) {
            case RecordedEvent.Output o -> comparison.expectOutput(o.method(), o.output(), o.sample());
            case RecordedEvent.Command c -> {
                if (c.sent()) {
                    comparison.expectCommand(c.iface(), c.channel(), c.sample());
                }
            }
            case RecordedEvent.Dropped d -> recordedDrops = d.total();
            case RecordedEvent.Audit a -> { } // who drove: nothing to run again
            case RecordedEvent.Skip s -> { } // read before the replay began (the graph's RecordedSkips)
            case RecordedEvent.End x -> complete = true;
            case RecordedEvent.Reading r -> {
                advance(r.t());
                graph.replay().reading(r.iface(), r.channel(), r.sample().payload(), r.sample().sourceMicros());
                readings++;
                settle();
            }
            case RecordedEvent.LinkChange l -> {
                advance(l.t());
                graph.replay().link(l.iface(), l.up());
                settle();
            }
            case RecordedEvent.ControlWrite w -> {
                if (options.controlWrites()) {
                    advance(w.t());
                    write(w);
                    settle();
                }
            }
            case RecordedEvent.WriterLeft w -> {
                if (options.controlWrites()) {
                    advance(w.t());
                    point(w.socket()).ifPresent(ControlPoint::writerLeft);
                    settle();
                }
            }
            case RecordedEvent.Tick k -> {
                if (recordedTicks) {
                    advance(k.t());
                    if (graph.replay().periodic(k.task())) {
                        ticks++;
                    }
                    settle();
                }
            }
        }
    }

    private Optional<ControlPoint> point(String socket) {
        return graph.controlPoints().stream().filter(p -> p.name().equals(socket)).findFirst();
    }

    /**
     * Runs now, before an event at {@code t} is fed (a reading, a control write), every method tick recorded
     * a little later whose method had then taken exactly as many samples as it has now, if the event can
     * reach that method: in the recorded run the tick came before the event's effect arrived (it was still
     * on its way through the layers), and so it must here.
     */
    void ticksTakenBefore(long t, java.util.function.Predicate<String> reaches, Deque<RecordedEvent> ahead)
            throws InterruptedException {
        if (!recordedTicks) {
            return;
        }
        Set<String> looked = new HashSet<>();
        for (Iterator<RecordedEvent> it = ahead.iterator(); it.hasNext(); ) {
            if (!(it.next() instanceof RecordedEvent.Tick k) || !k.task().startsWith(Replayer.TICK_PREFIX) || k.handled() < 0) {
                continue;
            }
            String method = k.task().substring(Replayer.TICK_PREFIX.length());
            if (!looked.add(method) || k.t() - t > Replayer.LOOKAHEAD_MICROS || !reaches.test(method)
                    || graph.replay().handled(method) != k.handled()) {
                continue;
            }
            it.remove();
            advance(k.t());
            if (graph.replay().periodic(k.task())) {
                ticks++;
            }
            settle();
        }
    }

    private void write(RecordedEvent.ControlWrite w) {
        ControlPoint point = point(w.socket()).orElse(null);
        Input<?> input = point == null ? null : point.controlInputs().stream()
                .filter(i -> i.name().equals(w.input())).findFirst().orElse(null);
        if (input == null) {
            rejected++;
            LOG.warn("replay: the config has no control input {}.{}; a recorded write was skipped", w.socket(), w.input());
            return;
        }
        try {
            point.write(input, w.sample().payload());
            controlWrites++;
        } catch (ControlPoint.Rejected ex) {
            rejected++;
            LOG.warn("replay: control write to {} refused: {}", w.socket(), ex.getMessage());
        }
    }

    private void advance(long t) throws InterruptedException {
        if (options.speed() > 0) {
            long dueNanos = wallStartNanos + (long) ((t - startMicros) * 1_000 / options.speed());
            long wait = dueNanos - System.nanoTime();
            if (wait > 0) {
                TimeUnit.NANOSECONDS.sleep(wait);
            }
        }
        lastMicros = Math.max(lastMicros, t);
        clock.advanceTo(t, !recordedTicks, () -> {
            ticks++;
            settleQuietly();
        });
    }

    void settle() throws InterruptedException {
        if (!graph.awaitIdle(options.settleMillis())) {
            unsettled++;
            if (unsettled == 1) {
                LOG.warn("replay: the graph did not go idle within {} ms; going on", options.settleMillis());
            }
        }
    }

    private void settleQuietly() {
        try {
            settle();
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
        }
    }
}
