package org.habla.recording;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.graph.EngineClock;
import org.habla.graph.GraphTap;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Writes what a running graph's tap sees to an append-only recording file, from a thread of its own.
 *
 * <pre>
 *   the file: records of the control codec, one after another, nothing between them
 *   +-------------------------------------------------------------+----+  +---------------------------+
 *   | {"type":"reading","t":T,"iface":"robot","channel":"sonar",   | \n |  | N raw bytes, only if the   |
 *   |  "producer":..,"seq":..,"src":..,"stale":..,"kind":..,       |    |  | line declares "bytes": N   |
 *   |  "value":..  or  "rateHz"/"width"/..,"bytes":N}              |    |  | (audio PCM, image data)    |
 *   +-------------------------------------------------------------+----+  +---------------------------+
 *   first record: {"type":"recording","format":"habla-recording","version":1,"config":{..},"interfaces":{..}}
 *   then:  reading | command | control | left | output | link | tick | dropped   ...   and on a clean close: end
 * </pre>
 *
 * The engine's threads only put an event on a bounded queue ({@link #QUEUE_EVENTS} events, at most
 * {@link #QUEUE_BYTES} bytes of audio and images); when it is full the event is dropped and counted, never
 * waited for, and the count goes into the file as a {@code dropped} record. The writer thread flushes to the
 * operating system every {@link #FLUSH_MILLIS} ms, so a daemon killed with SIGKILL loses at most that much,
 * and the reader recognises the torn last record. A failed disk stops the recording (logged once), never the
 * daemon.
 */
public final class Recorder implements GraphTap, AutoCloseable {

    /** The most events waiting for the writer. */
    public static final int QUEUE_EVENTS = 65_536;
    /** The most bytes of audio and image data waiting for the writer. */
    public static final long QUEUE_BYTES = 64L << 20;
    /** How often the writer hands what it wrote to the operating system. */
    public static final long FLUSH_MILLIS = 100;

    private static final Logger LOG = LoggerFactory.getLogger(Recorder.class);
    private static final RecordedEvent STOP = new RecordedEvent.End(0, 0, 0);
    /** Marks the point up to which {@link #flush} waits; never written. */
    private static final RecordedEvent FLUSH = new RecordedEvent.End(0, 0, 0);

    private final Path file;
    private final EngineClock clock;
    private final OutputStream stream;
    private final EventFile out;
    private final BlockingQueue<RecordedEvent> queue = new ArrayBlockingQueue<>(QUEUE_EVENTS + 1);
    private final AtomicLong queuedBytes = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong written = new AtomicLong();
    private final Thread writer;
    private volatile boolean closed;
    private volatile boolean failed;
    private volatile long writerCpuAtEnd = -1;
    private final java.util.concurrent.Semaphore flushed = new java.util.concurrent.Semaphore(0);

    private Recorder(Path file, EngineClock clock, OutputStream stream, EventFile out) {
        this.file = file;
        this.clock = clock;
        this.stream = stream;
        this.out = out;
        this.writer = new Thread(this::writeLoop, "habla-recorder");
        this.writer.setDaemon(true);
    }

    /**
     * Creates {@code file} (it must not exist yet: a recording is never overwritten), writes the header and
     * starts the writer thread.
     */
    public static Recorder create(Path file, RecordingHeader header, EngineClock clock) throws IOException {
        OutputStream s = Files.newOutputStream(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        Recorder r;
        try {
            r = new Recorder(file, clock, s, EventFile.create(file, s, header));
        } catch (IOException e) {
            s.close();
            throw e;
        }
        r.writer.start();
        LOG.info("recording to {}", file);
        return r;
    }

    public Path file() {
        return file;
    }

    /** Events dropped because the writer fell behind. */
    public long dropped() {
        return dropped.get();
    }

    /** CPU time the writer thread has used so far (encoding, compressing, writing), ns; -1 if not measurable. */
    public long writerCpuNanos() {
        if (!writer.isAlive()) {
            return writerCpuAtEnd;
        }
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        return mx.isThreadCpuTimeSupported() ? mx.getThreadCpuTime(writer.threadId()) : -1;
    }

    /** Events written so far (the header not counted). */
    public long written() {
        return written.get();
    }

    // ------------------------------------------------------------------ GraphTap (engine threads)

    @Override
    public void reading(String interfaceId, String channel, Sample sample) {
        offer(new RecordedEvent.Reading(clock.nowMicros(), interfaceId, channel, sample), bytes(sample));
    }

    @Override
    public void command(String interfaceId, String channel, Sample sample, boolean sent) {
        offer(new RecordedEvent.Command(clock.nowMicros(), interfaceId, channel, sample, sent), bytes(sample));
    }

    @Override
    public void control(String socket, String input, Sample sample) {
        offer(new RecordedEvent.ControlWrite(clock.nowMicros(), socket, input, sample), bytes(sample));
    }

    @Override
    public void writerLeft(String socket) {
        offer(new RecordedEvent.WriterLeft(clock.nowMicros(), socket), 0);
    }

    @Override
    public void audit(org.habla.security.AuditEntry entry) {
        offer(new RecordedEvent.Audit(clock.nowMicros(), entry.json()), 0);
    }

    @Override
    public void link(String interfaceId, boolean up, long micros) {
        offer(new RecordedEvent.LinkChange(micros, interfaceId, up), 0);
    }

    @Override
    public void output(String methodId, String output, Sample sample) {
        offer(new RecordedEvent.Output(clock.nowMicros(), methodId, output, sample), bytes(sample));
    }

    @Override
    public void skipped(String methodId, String input, long arrival) {
        offer(new RecordedEvent.Skip(clock.nowMicros(), methodId, input, arrival), 0);
    }

    @Override
    public void periodic(String task, long micros, long handled) {
        offer(new RecordedEvent.Tick(micros, task, handled), 0);
    }

    private void offer(RecordedEvent e, long bytes) {
        if (closed || failed) {
            return;
        }
        if (queuedBytes.addAndGet(bytes) > QUEUE_BYTES || queue.size() >= QUEUE_EVENTS || !queue.offer(e)) {
            queuedBytes.addAndGet(-bytes);
            long n = dropped.incrementAndGet();
            if (n == 1 || n % 1000 == 0) {
                LOG.warn("recording {}: the writer is behind; {} events dropped so far", file, n);
            }
        }
    }

    private static long bytes(Sample s) {
        return switch (s.payload()) {
            case AudioChunk a -> a.byteCount();
            case ImageFrame f -> f.byteCount();
            default -> 0;
        };
    }

    // ------------------------------------------------------------------ the writer thread

    private void writeLoop() {
        long nextFlush = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(FLUSH_MILLIS);
        long droppedWritten = 0;
        try {
            while (true) {
                long wait = nextFlush - System.nanoTime();
                RecordedEvent e = wait > 0 ? queue.poll(wait, TimeUnit.NANOSECONDS) : queue.poll();
                if (e == STOP) {
                    break;
                }
                if (e == FLUSH) {
                    out.flush();
                    flushed.release();
                    continue;
                }
                if (e != null) {
                    queuedBytes.addAndGet(-(e instanceof RecordedEvent.End ? 0 : bytesOf(e)));
                    out.write(e);
                    written.incrementAndGet();
                }
                if (System.nanoTime() - nextFlush >= 0) {
                    long d = dropped.get();
                    if (d != droppedWritten) {
                        out.write(new RecordedEvent.Dropped(clock.nowMicros(), d));
                        droppedWritten = d;
                    }
                    out.flush();
                    nextFlush = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(FLUSH_MILLIS);
                }
            }
            for (RecordedEvent e = queue.poll(); e != null; e = queue.poll()) {
                if (e == FLUSH) {
                    flushed.release();
                } else if (e != STOP) {
                    out.write(e);
                    written.incrementAndGet();
                }
            }
            out.write(new RecordedEvent.End(clock.nowMicros(), written.get(), dropped.get()));
            out.finish();
        } catch (IOException e) {
            failed = true;
            LOG.error("recording {} stopped: cannot write: {}", file, e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
            writerCpuAtEnd = mx.isCurrentThreadCpuTimeSupported() ? mx.getCurrentThreadCpuTime() : -1;
            try {
                stream.close();
            } catch (IOException e) {
                LOG.debug("closing {}: {}", file, e.toString());
            }
        }
    }

    private static long bytesOf(RecordedEvent e) {
        return switch (e) {
            case RecordedEvent.Reading r -> bytes(r.sample());
            case RecordedEvent.Command c -> bytes(c.sample());
            case RecordedEvent.ControlWrite w -> bytes(w.sample());
            case RecordedEvent.Output o -> bytes(o.sample());
            default -> 0;
        };
    }

    /**
     * Waits until every event offered before this call is written and handed to the operating system (for
     * MCAP, its chunk is closed); false if the writer did not get there within {@code timeoutMillis}.
     */
    public boolean flush(long timeoutMillis) throws InterruptedException {
        if (closed || failed || !queue.offer(FLUSH)) {
            return false;
        }
        return flushed.tryAcquire(timeoutMillis, TimeUnit.MILLISECONDS);
    }

    /** Writes what is queued, then the end record, and closes the file. Safe to call twice. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        queue.offer(STOP);
        try {
            writer.join(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        LOG.info("recording {} closed: {} events written, {} dropped", file, written.get(), dropped.get());
    }
}
