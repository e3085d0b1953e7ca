package org.habla.graph;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/**
 * The engine's side of one producer — a method's output or an interface's reading channel: it
 * numbers samples, remembers the newest and hands each to every subscriber (input slots, command
 * channels, control clients). Subscribers must not block.
 */
final class Producer {

    private final String producer;
    private final List<Consumer<Sample>> subscribers = new CopyOnWriteArrayList<>();
    /** How many subscribers at the head of the list were added ahead of the others. */
    private int ahead;
    private final AtomicLong sequence = new AtomicLong();
    /** The newest sample; written with release (readers need only see it soon), read as a volatile. */
    private volatile Sample latest;
    private static final java.lang.invoke.VarHandle LATEST;

    static {
        try {
            LATEST = java.lang.invoke.MethodHandles.lookup().findVarHandle(Producer.class, "latest", Sample.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
    /** Sees every sample before the subscribers do; set while the graph is built, before anything publishes. */
    private Consumer<Sample> first = s -> { };

    Producer(String producer) {
        this.producer = producer;
    }

    String producer() {
        return producer;
    }

    void subscribe(Consumer<Sample> subscriber) {
        subscribers.add(subscriber);
    }

    /**
     * Adds a subscriber that gets each sample before the ones added by {@link #subscribe} (after the others added
     * here): a method run on this producer's thread, so a light chain is not kept waiting while other methods'
     * threads are woken. Called while the graph is built.
     */
    void subscribeAhead(Consumer<Sample> subscriber) {
        subscribers.add(ahead++, subscriber);
    }

    void unsubscribe(Consumer<Sample> subscriber) {
        subscribers.remove(subscriber);
    }

    /**
     * Has {@code tap} (a recording's, at the graph's edge) see every sample before any subscriber does, so the
     * sample is written down before any of its effects can be. Called while the graph is built.
     */
    void tapFirst(Consumer<Sample> tap) {
        this.first = tap;
    }

    /** Makes a sample of {@code payload}, shows it to the tap, then hands it to every subscriber. */
    Sample publish(Payload payload, long sourceMicros, boolean stale) {
        Sample s = new Sample(payload, producer, sequence.incrementAndGet(), sourceMicros, stale);
        first.accept(s);
        LATEST.setRelease(this, s);
        for (Consumer<Sample> sub : subscribers) {
            sub.accept(s);
        }
        return s;
    }

    Sample latest() {
        return latest;
    }

    long published() {
        return sequence.get();
    }
}
