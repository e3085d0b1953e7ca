package org.habla.graph;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.OptionalInt;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Real-time scheduling for the daemon's sample path, on Linux, when a deployment asks for it with the system
 * property {@value #PROPERTY} (a priority, 1 to 99). The threads a sample crosses between a robot and a control
 * socket — each interface's link thread, each method's thread, the engine clock's and the carriers of the
 * virtual threads that write the control sockets — then run in the {@code SCHED_FIFO} class: a thread of that class
 * that wakes takes a core from any normal thread at once. Without it, a woken thread may wait until the thread on
 * the core has run its time slice, which on a machine whose cores are also busy with speech, vision or the robot's
 * own I/O is the light chain's millisecond tail (docs/performance.md (k)); nice values do not shorten that wait.
 * Heavy work stays normal: each raised thread is set to reset on fork, so the threads it starts (the background
 * pool's, a model's) begin in the normal class.
 *
 * <p>The class is set with the system's {@code chrt}, once per thread. Linux lets a process do so with the
 * {@code CAP_SYS_NICE} capability or an {@code RLIMIT_RTPRIO} of at least the priority (systemd's
 * {@code LimitRTPRIO=}, {@code ulimit -r}); without it one line says so and the threads stay normal.
 */
public final class RealtimeThreads {

    /** The system property that asks for real-time scheduling of the sample path, at this priority (1 to 99). */
    public static final String PROPERTY = "habla.realtimePriority";

    private static final Logger LOG = LoggerFactory.getLogger(RealtimeThreads.class);
    /** How often the carriers of virtual threads are looked for: the JDK starts them when it needs them. */
    private static final long CARRIER_SWEEP_MILLIS = 1_000;
    /** {@code /proc/.../stat}'s field 41, the scheduling class, for {@code SCHED_FIFO}. */
    static final int SCHED_FIFO = 1;
    /** Set at the first refusal: said once, and no thread tries again (each try starts a process). */
    private static final AtomicBoolean REFUSED = new AtomicBoolean();
    /** The graphs of this JVM that keep the carriers raised, and the thread that does it while there are any. */
    private static int carrierUsers;
    private static Thread carrierSweeper;

    private RealtimeThreads() {
    }

    /**
     * The priority {@value #PROPERTY} asks for, 0 when unset or 0; checked when the graph is built, so that a
     * wrong value stops the start rather than a thread.
     *
     * @throws IllegalArgumentException for anything but 0 to 99
     */
    public static int configured() {
        return priority(System.getProperty(PROPERTY));
    }

    static int priority(String property) {
        return ThreadNice.property(PROPERTY, property, 99, "0 (normal scheduling) or a real-time priority of 1 to 99");
    }

    /**
     * The priority asked for, 0 for none or for a wrong value (a wrong value is reported by the graph's build,
     * {@link #configured}, not by each thread). Read it where a thread is started, not in the thread.
     */
    static int asked() {
        try {
            return configured();
        } catch (IllegalArgumentException e) {
            return 0;
        }
    }

    /** Raises the calling thread if the deployment asked for it; false where it did not or could not. */
    public static boolean raiseCurrentIfAsked() {
        return raiseCurrentTo(asked());
    }

    /** Raises the calling thread to {@code priority}, 0 for none; false where it was not raised. */
    static boolean raiseCurrentTo(int priority) {
        return priority > 0 && raiseCurrent(priority);
    }

    /**
     * Puts the calling thread in {@code SCHED_FIFO} at {@code priority}, reset on fork; false, logged once, where it
     * cannot.
     */
    static boolean raiseCurrent(int priority) {
        OptionalInt tid = ThreadNice.threadId();
        if (tid.isEmpty()) {
            return cannot("no /proc/thread-self");
        }
        return raise(tid.getAsInt(), priority);
    }

    private static boolean raise(int tid, int priority) {
        return chrt(tid, "--fifo", "--reset-on-fork", "--pid", Integer.toString(priority));
    }

    /**
     * Runs {@code chrt OPTIONS... TID}; false where it fails, and after the first refusal (said once) without trying.
     */
    private static boolean chrt(int tid, String... options) {
        if (REFUSED.get()) {
            return false;
        }
        List<String> command = new ArrayList<>(List.of("chrt"));
        command.addAll(List.of(options));
        command.add(Integer.toString(tid));
        Process p = null;
        try {
            p = new ProcessBuilder(command).redirectErrorStream(true).start();
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return cannot("chrt did not end within 10 s");
            }
            String said = new String(p.getInputStream().readAllBytes()).strip();
            if (p.exitValue() != 0 && !Files.exists(Path.of("/proc/self/task/" + tid))) {
                return false; // the thread ended meanwhile (a carrier the JDK let go): not a refusal
            }
            return p.exitValue() == 0 || cannot("chrt exited with " + p.exitValue() + (said.isEmpty() ? "" : ": "
                    + said.lines().findFirst().orElse("")));
        } catch (IOException e) {
            return cannot(e.getMessage());
        } catch (InterruptedException e) {
            // chrt runs on: let it end before anything else asks (a hand-back must not come before this raise)
            p.onExit().orTimeout(10, TimeUnit.SECONDS).exceptionally(t -> null).join();
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** The scheduling class of one of this process's threads, as Linux reports it ({@code SCHED_FIFO} is 1). */
    static OptionalInt policy(int tid) {
        try {
            String stat = Files.readString(Path.of("/proc/self/task/" + tid + "/stat"));
            String[] after = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return OptionalInt.of(Integer.parseInt(after[38]));
        } catch (IOException | RuntimeException e) {
            return OptionalInt.empty();
        }
    }

    /**
     * Raises the carriers of virtual threads, now and whenever the JDK starts another, until closed, and then —
     * when no other graph of this JVM still asks — returns them to normal scheduling (they serve the whole JVM);
     * nothing when the deployment did not ask. The carriers are found by name: a virtual thread started here
     * reports the name of the carrier it runs on.
     */
    static AutoCloseable raiseCarriersIfAsked() {
        int priority = configured();
        if (priority == 0) {
            return () -> { };
        }
        synchronized (RealtimeThreads.class) {
            if (carrierUsers++ == 0) {
                carrierSweeper = carrierSweeper(priority);
            }
        }
        AtomicBoolean closed = new AtomicBoolean();
        return () -> {
            Thread stop = null;
            synchronized (RealtimeThreads.class) {
                if (closed.compareAndSet(false, true) && --carrierUsers == 0) {
                    stop = carrierSweeper;
                    carrierSweeper = null;
                }
            }
            if (stop != null) {
                stop.interrupt();
                stop.join(10_000);
            }
        };
    }

    /** The thread that raises the carriers until interrupted, then hands them back; null where it cannot run. */
    private static Thread carrierSweeper(int priority) {
        String prefix = carrierPrefix();
        if (prefix == null) {
            cannot("the carriers of virtual threads have no name to find them by");
            return null;
        }
        // Linux keeps the first 15 bytes of a thread's name.
        String comm = prefix.length() > 15 ? prefix.substring(0, 15) : prefix;
        return Thread.ofPlatform().daemon().name("habla-realtime-carriers").start(() -> {
            Set<Integer> seen = new HashSet<>();
            // Every carrier a raise was begun for: a close that interrupts the wait for chrt does not stop chrt
            // itself, which may still raise the thread, so each one begun is handed back, raised or not.
            List<Integer> raised = new ArrayList<>();
            try {
                while (!Thread.currentThread().isInterrupted()) {
                    try (DirectoryStream<Path> tasks = Files.newDirectoryStream(Path.of("/proc/self/task"))) {
                        for (Path task : tasks) {
                            int tid = Integer.parseInt(task.getFileName().toString());
                            if (seen.add(tid) && startsWith(task, comm)) {
                                raised.add(tid);
                                chrt(tid, "--fifo", "--reset-on-fork", "--pid", Integer.toString(priority));
                            }
                        }
                    }
                    Thread.sleep(CARRIER_SWEEP_MILLIS);
                }
            } catch (IOException | NumberFormatException e) {
                cannot("cannot list this process's threads: " + e.getMessage());
            } catch (InterruptedException e) {
                // closed: the carriers serve whatever runs in this JVM next at normal scheduling again
            } finally {
                Thread.interrupted(); // the flag would stop each chrt below before it ran
                for (int tid : raised) {
                    chrt(tid, "--other", "--pid", "0");
                }
            }
        });
    }

    /** Whether a thread's Linux name starts with {@code comm}; false for a thread that ended since it was listed. */
    static boolean startsWith(Path task, String comm) {
        try {
            return Files.readString(task.resolve("comm")).strip().startsWith(comm);
        } catch (IOException e) {
            return false;
        }
    }

    /** {@code ForkJoinPool-1-worker-} for a carrier named {@code ForkJoinPool-1-worker-3}, or null. */
    static String carrierPrefix() {
        AtomicReference<String> seen = new AtomicReference<>();
        Thread v = Thread.ofVirtual().start(() -> seen.set(Thread.currentThread().toString()));
        try {
            v.join(java.time.Duration.ofSeconds(5));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
        String s = seen.get(); // VirtualThread[#31]/runnable@ForkJoinPool-1-worker-1
        int at = s == null ? -1 : s.lastIndexOf('@');
        if (at < 0) {
            return null;
        }
        String carrier = s.substring(at + 1);
        int dash = carrier.lastIndexOf('-');
        return dash <= 0 ? null : carrier.substring(0, dash + 1);
    }

    private static boolean cannot(String why) {
        if (REFUSED.compareAndSet(false, true)) {
            LOG.warn("the sample path keeps normal scheduling: -D{} (config/daemon.jvm-options) asks for real-time"
                    + " threads, but they cannot be made so ({}); Linux allows it with CAP_SYS_NICE or an rtprio limit"
                    + " (LimitRTPRIO= in a systemd unit, ulimit -r; docs/deployment.md); -D{}=0 asks for nothing",
                    PROPERTY, why, PROPERTY);
        }
        return false;
    }
}
