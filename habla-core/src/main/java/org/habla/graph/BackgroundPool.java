package org.habla.graph;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The threads a daemon or a worker runs its methods' heavy work on ({@code background(..)}: loading models,
 * decoding speech, segmenting images): one per core, at least two, daemon threads at the lowest Java priority, so
 * heavy work yields to the method threads wherever the JVM maps priorities to the system's (with
 * {@code -XX:ThreadPriorityPolicy=1}: an option a deployment may add, not a default; docs/deployment.md). With the
 * system property {@value #NICE_PROPERTY} (1 to 19) each thread sets its own nice value on Linux when it starts
 * ({@link ThreadNice}), which a deployment whose control loop shares the cores with speech and vision may set.
 */
public final class BackgroundPool {

    /** The system property that gives the pool's threads a nice value (1 to 19) on Linux; 0 or unset: none. */
    public static final String NICE_PROPERTY = "habla.backgroundNice";

    private BackgroundPool() {
    }

    /**
     * A new pool whose threads are named {@code prefix} and a number.
     *
     * @throws IllegalArgumentException if {@value #NICE_PROPERTY} is set to anything but 0 to 19
     */
    public static ExecutorService create(String prefix) {
        AtomicInteger n = new AtomicInteger();
        int nice = niceValue(System.getProperty(NICE_PROPERTY));
        return Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()), r -> {
            Runnable body = nice <= 0 ? r : () -> {
                ThreadNice.lowerTo(nice);
                r.run();
            };
            Thread t = new Thread(body, prefix + n.incrementAndGet());
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            return t;
        });
    }

    /** The nice value the property asks for, checked here so that a wrong one stops the start, not a thread. */
    static int niceValue(String property) {
        return ThreadNice.property(NICE_PROPERTY, property, 19, "0 (none) or a nice value of 1 to 19");
    }
}
