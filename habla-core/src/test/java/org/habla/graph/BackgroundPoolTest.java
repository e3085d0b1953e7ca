package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

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

    @Test
    void withANiceValueConfiguredTheHeavyThreadsRunAtThatNiceValueAndTheCallerKeepsItsOwn() throws Exception {
        assumeTrue(ThreadNice.current().isPresent(), "Linux reports no nice value per thread here");
        int callerBefore = ThreadNice.current().getAsInt();
        assumeTrue(callerBefore < 19, "this test already runs at nice 19");
        System.setProperty(BackgroundPool.NICE_PROPERTY, "19");
        ExecutorService pool;
        try {
            pool = BackgroundPool.create("test-nice-");
        } finally {
            System.clearProperty(BackgroundPool.NICE_PROPERTY);
        }
        try {
            int nice = pool.submit(() -> ThreadNice.current().orElse(-100)).get(20, TimeUnit.SECONDS);
            assertThat(nice).isEqualTo(19);
        } finally {
            pool.shutdownNow();
        }
        assertThat(ThreadNice.current()).hasValue(callerBefore);
    }

    @Test
    void withoutANiceValueConfiguredTheHeavyThreadsKeepTheProcessNiceValue() throws Exception {
        assumeTrue(ThreadNice.current().isPresent(), "Linux reports no nice value per thread here");
        int caller = ThreadNice.current().getAsInt();
        ExecutorService pool = BackgroundPool.create("test-plain-");
        try {
            assertThat(pool.submit(() -> ThreadNice.current().orElse(-100)).get(10, TimeUnit.SECONDS))
                    .isEqualTo(caller);
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void aNiceValueOutsideZeroToNineteenIsRefusedNamingTheProperty() {
        assertThat(BackgroundPool.niceValue(null)).isZero();
        assertThat(BackgroundPool.niceValue(" 7 ")).isEqualTo(7);
        for (String wrong : new String[] {"20", "-1", "low"}) {
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> BackgroundPool.niceValue(wrong))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining(BackgroundPool.NICE_PROPERTY).hasMessageContaining("'" + wrong + "'");
        }
    }
}
