package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;

class OutageLogTest {

    private final AtomicLong nanos = new AtomicLong(1_000);

    private void advanceSeconds(long s) {
        nanos.addAndGet(TimeUnit.SECONDS.toNanos(s));
    }

    @Test
    void aLinkThatStaysDownWarnsOnceThenSummarisesEveryMinute() {
        try (LogLines lines = new LogLines(OutageLogTest.class)) {
            OutageLog log = new OutageLog(LoggerFactory.getLogger(OutageLogTest.class), "link robot/arcos", nanos::get);
            log.failed("Connection refused");
            for (int i = 0; i < 299; i++) {
                nanos.addAndGet(TimeUnit.MILLISECONDS.toNanos(199));
                log.failed("Connection refused");
            }
            assertThat(lines.at(Level.WARN)).as("300 attempts in 59.5 s").containsExactly(
                    "link robot/arcos down: Connection refused");
            advanceSeconds(1);
            log.failed("connect timed out");
            assertThat(lines.at(Level.WARN)).hasSize(2).last().isEqualTo(
                    "link robot/arcos still down after 301 failed attempts in 60.5 s: connect timed out");
            advanceSeconds(30);
            log.failed("connect timed out");
            assertThat(lines.at(Level.WARN)).as("not again before another minute").hasSize(2);
            advanceSeconds(4);
            log.up();
            assertThat(lines.at(Level.INFO)).containsExactly(
                    "link robot/arcos up again after 94.5 s down (302 failed attempts)");
            log.failed("the robot closed the connection");
            assertThat(lines.at(Level.WARN)).as("a new outage is told at once").hasSize(3).last().isEqualTo(
                    "link robot/arcos down: the robot closed the connection");
        }
    }
}
