// Over 300 lines, on purpose: one lock guards the queue, the rate limit's held samples, the drop count and who owns
// the socket's writing side (the writer or a direct sender); split, the parts would have to share that lock.
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
 * One writer thread takes batches with {@link #take} and says when it has {@link #sent} them. An engine thread may
 * instead write a sample to the socket itself when nothing waits here and nobody is writing: it
 * {@link #claimDirect claims} the writing side, writes what the socket takes at once, and hands back the rest
 * ({@link #releaseDirect}), which goes out first. Since when lines have waited for the peer ({@link #waitingSinceNanos})
 * is what the port's idle deadline reads: a client that takes what it is sent is never idle, however quiet.
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
    /** Whether the writer or a direct sender is writing to the socket now. */
    private boolean sending;
    /** Whether the writer is writing a batch now (a direct sender's write never waits, so it is not counted). */
    private boolean writing;
    /** Since when lines have waited for the peer to take them ({@link System#nanoTime()}), 0 while none wait. */
    private long waitingSinceNanos;

    private record Entry(EncodedFrame frame, Kind kind) {
    }

    /** PARTIAL: the unsent end of a line written directly, never dropped. */
    private enum Kind { SAMPLE, REPLY, NOTICE, PARTIAL }

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
            noteWaiting();
            changed.signal();
            return dropped;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Claims the socket's writing side for a sample written directly, if nothing waits to be written, nobody
     * writes, no drop is untold and no rate limit holds samples back.
     *
     * @return whether the caller now owns the writing side and must {@link #releaseDirect} it
     */
    boolean claimDirect() {
        lock.lock();
        try {
            if (finished || sending || !queue.isEmpty() || minIntervalNanos > 0 || droppedUntold > 0) {
                return false;
            }
            sending = true;
            return true;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Gives back the writing side after a direct write; {@code rest}, if not null, is what the socket did not take:
     * the whole sample ({@code whole}), which may still be dropped like any queued one, or the end of a line
     * begun, which is written next whatever happens.
     */
    void releaseDirect(EncodedFrame rest, boolean whole) {
        lock.lock();
        try {
            sending = false;
            if (rest != null) {
                if (!whole) {
                    queue.addFirst(new Entry(rest, Kind.PARTIAL));
                } else if (!finished) {
                    if (samples == sampleCapacity) {
                        dropOldestSample();
                    }
                    queue.addFirst(new Entry(rest, Kind.SAMPLE));
                    samples++;
                }
            }
            if (!queue.isEmpty()) {
                noteWaiting();
                changed.signalAll(); // the writer, who waited for the writing side; otherwise it sleeps on
            }
        } finally {
            lock.unlock();
        }
    }

    /** The writer has written the batch {@link #take} gave it. */
    void sent() {
        lock.lock();
        try {
            sending = false;
            writing = false;
            noteWaiting();
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Queues a reply, waiting while {@code replyCapacity} replies are unsent; dropped once finished. */
    void putReply(EncodedFrame frame) throws InterruptedException {
        putReply(frame, () -> { });
    }

    /**
     * Queues a reply, then runs {@code queued} under the outbox's lock, before the writer can take the reply or a
     * sample can be written past it: a client told it is admitted only as its hello is queued never misses a sample
     * emitted after the hello reached it.
     */
    void putReply(EncodedFrame frame, Runnable queued) throws InterruptedException {
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
            queued.run();
            noteWaiting();
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
            noteWaiting();
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
     * since the last one. Blocks until something is ready and nobody else writes; the caller then owns the writing
     * side until it calls {@link #sent}.
     *
     * @return the batch, or {@code null} once {@link #finish}ed and empty
     */
    List<EncodedFrame> take() throws InterruptedException {
        lock.lock();
        try {
            while (true) {
                long wait = releaseDueSamples();
                if (!queue.isEmpty()) {
                    if (!sending) {
                        sending = true;
                        writing = true;
                        return drain();
                    }
                } else if (finished) {
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
            queue.removeIf(e -> e.kind != Kind.PARTIAL); // a line begun is ended before the last one
            held.clear();
            samples = 0;
            replies = 0;
            queue.add(new Entry(last, Kind.REPLY));
            noteWaiting();
            finished = true;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /**
     * Since when lines have waited here or in the writer's hands for the peer to take them
     * ({@link System#nanoTime()}), or 0 while none do.
     */
    long waitingSinceNanos() {
        lock.lock();
        try {
            return waitingSinceNanos;
        } finally {
            lock.unlock();
        }
    }

    /** Notes whether lines wait now; called under the lock after every change to the queue or the writer. */
    private void noteWaiting() {
        if (queue.isEmpty() && !writing) {
            waitingSinceNanos = 0;
        } else if (waitingSinceNanos == 0) {
            waitingSinceNanos = System.nanoTime() | 1; // never 0
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
                noteWaiting();
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
