package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class BackgroundPoolTest {

    @Test
    void heavyWorkRunsOnNamedDaemonThreadsAtTheLowestPriority() throws Exception {
        ExecutorService pool = BackgroundPool.create("test-heavy-");
        try {
            Thread t = pool.submit(Thread::currentThread).get(10, TimeUnit.SECONDS);
            assertThat(t.getName()).startsWith("test-heavy-");
            assertThat(t.isDaemon()).isTrue();
            assertThat(t.getPriority()).isEqualTo(Thread.MIN_PRIORITY);
        } finally {
            pool.shutdownNow();
        }
    }
}
