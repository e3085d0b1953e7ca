package org.habla.graph;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The threads a daemon or a worker runs its methods' heavy work on ({@code background(..)}: loading models,
 * decoding speech, segmenting images): one per core, at least two, daemon threads at the lowest Java priority, so
 * heavy work yields to the method threads wherever the JVM maps priorities to the system's (with
 * {@code -XX:ThreadPriorityPolicy=1}: an option a deployment may add, not a default; docs/deployment.md).
 */
public final class BackgroundPool {

    private BackgroundPool() {
    }

    /** A new pool whose threads are named {@code prefix} and a number. */
    public static ExecutorService create(String prefix) {
        AtomicInteger n = new AtomicInteger();
        return Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()), r -> {
            Thread t = new Thread(r, prefix + n.incrementAndGet());
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            return t;
        });
    }
}
