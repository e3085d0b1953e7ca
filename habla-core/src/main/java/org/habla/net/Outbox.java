package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * What waits to be written to one control client, in order: samples, replies and notices, each already encoded
 * (a sample once for all the clients of its socket).
 *
 * <ul>
 *   <li>Samples come from engine threads and never wait: at most {@code sampleCapacity} are held; the
 *       oldest is dropped to make room, counted, and the client is told before its next sample line.
 *       A client's rate limit holds back the newest sample of an output until it is due.</li>
 *   <li>Replies come from the client's own reader and wait for room (at most {@code replyCapacity}), so a
 *       client that asks faster than it reads only slows itself.</li>
 *   <li>Notices (staleness, who commands the socket, ...) never wait and never pile up: a newer one replaces one
 *       of the same type not yet sent.</li>
 * </ul>
 * One writer thread takes batches with {@link #take}.
 */
final class Outbox {

    private final int sampleCapacity;
    private final int replyCapacity;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private final ArrayDeque<Entry> queue = new ArrayDeque<>();
    private final Map<String, Long> lastSampleNanos = new HashMap<>();
    private final Map<String, EncodedFrame> held = new HashMap<>();
    private int samples;
    private int replies;
    private long minIntervalNanos;
    private long droppedUntold;
    private long droppedTotal;
    private boolean finished;

    private record Entry(EncodedFrame frame, Kind kind) {
    }

    private enum Kind { SAMPLE, REPLY, NOTICE }

    Outbox(int sampleCapacity, int replyCapacity) {
        if (sampleCapacity < 1 || replyCapacity < 1) {
            throw new IllegalArgumentException("capacities must be at least 1");
        }
        this.sampleCapacity = sampleCapacity;
        this.replyCapacity = replyCapacity;
    }

    /**
     * Queues a sample of {@code output}; never blocks.
     *
     * @return whether an older sample was dropped to make room
     */
    boolean offerSample(String output, EncodedFrame frame) {
        lock.lock();
        try {
            if (finished) {
                return false;
            }
            if (minIntervalNanos > 0) {
                long now = System.nanoTime();
                Long last = lastSampleNanos.get(output);
                if (last != null && now - last < minIntervalNanos) {
                    held.put(output, frame);
                    changed.signal();
                    return false;
                }
                lastSampleNanos.put(output, now);
            }
            boolean dropped = false;
            if (samples == sampleCapacity) {
                dropOldestSample();
                dropped = true;
            }
            queue.add(new Entry(frame, Kind.SAMPLE));
            samples++;
            changed.signal();
            return dropped;
        } finally {
            lock.unlock();
        }
    }

    /** Queues a reply, waiting while {@code replyCapacity} replies are unsent; dropped once finished. */
    void putReply(EncodedFrame frame) throws InterruptedException {
        lock.lock();
        try {
            while (replies >= replyCapacity && !finished) {
                changed.await();
            }
            if (finished) {
                return;
            }
            queue.add(new Entry(frame, Kind.REPLY));
            replies++;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Queues a notice that replaces any notice of the same type not yet sent; never blocks. */
    void offerNotice(EncodedFrame frame) {
        lock.lock();
        try {
            if (finished) {
                return;
            }
            queue.removeIf(e -> e.kind == Kind.NOTICE && e.frame.type().equals(frame.type()));
            queue.add(new Entry(frame, Kind.NOTICE));
            changed.signal();
        } finally {
            lock.unlock();
        }
    }

    /** Limits samples to {@code maxHz} per output (0: no limit); the newest held sample is sent when due. */
    void rate(double maxHz) {
        lock.lock();
        try {
            minIntervalNanos = maxHz <= 0 ? 0 : (long) (1e9 / maxHz);
            changed.signal();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Takes everything ready to write, in order, preceded by a {@code dropped} notice if samples were dropped
     * since the last one. Blocks until something is ready.
     *
     * @return the batch, or {@code null} once {@link #finish}ed and empty
     */
    List<EncodedFrame> take() throws InterruptedException {
        lock.lock();
        try {
            while (true) {
                long wait = releaseDueSamples();
                if (!queue.isEmpty()) {
                    return drain();
                }
                if (finished) {
                    return null;
                }
                if (wait > 0) {
                    changed.awaitNanos(wait);
                } else {
                    changed.await();
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /** Accepts nothing more; {@link #take} returns what is left, then {@code null}. */
    void finish() {
        lock.lock();
        try {
            finished = true;
            held.clear();
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Drops whatever waits and accepts nothing more but {@code last}, which {@link #take} hands out next
     * (an eviction's error line); then {@code take} returns {@code null}.
     */
    void finishWith(EncodedFrame last) {
        lock.lock();
        try {
            if (finished) {
                return;
            }
            queue.clear();
            held.clear();
            samples = 0;
            replies = 0;
            queue.add(new Entry(last, Kind.REPLY));
            finished = true;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    long droppedTotal() {
        lock.lock();
        try {
            return droppedTotal;
        } finally {
            lock.unlock();
        }
    }

    private List<EncodedFrame> drain() {
        List<EncodedFrame> batch = new ArrayList<>(queue.size() + 1);
        boolean toldDrops = droppedUntold == 0;
        for (Entry e : queue) {
            if (e.kind == Kind.SAMPLE && !toldDrops) {
                batch.add(EncodedFrame.of(Frame.of(JsonNodeFactory.instance.objectNode().put("type", "dropped")
                        .put("count", droppedUntold).put("total", droppedTotal))));
                droppedUntold = 0;
                toldDrops = true;
            }
            batch.add(e.frame);
        }
        queue.clear();
        samples = 0;
        replies = 0;
        changed.signalAll();
        return batch;
    }

    /** Moves held samples that are due into the queue; returns nanoseconds until the next is due, or 0. */
    private long releaseDueSamples() {
        if (held.isEmpty()) {
            return 0;
        }
        long now = System.nanoTime();
        long next = Long.MAX_VALUE;
        for (Iterator<Map.Entry<String, EncodedFrame>> it = held.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<String, EncodedFrame> h = it.next();
            long due = lastSampleNanos.getOrDefault(h.getKey(), 0L) + minIntervalNanos;
            if (minIntervalNanos == 0 || now - due >= 0) {
                it.remove();
                lastSampleNanos.put(h.getKey(), now);
                if (samples == sampleCapacity) {
                    dropOldestSample();
                }
                queue.add(new Entry(h.getValue(), Kind.SAMPLE));
                samples++;
            } else {
                next = Math.min(next, due - now);
            }
        }
        return next == Long.MAX_VALUE ? 0 : Math.max(next, 1);
    }

    private void dropOldestSample() {
        for (Iterator<Entry> it = queue.iterator(); it.hasNext(); ) {
            if (it.next().kind == Kind.SAMPLE) {
                it.remove();
                samples--;
                droppedUntold++;
                droppedTotal++;
                return;
            }
        }
    }
}
