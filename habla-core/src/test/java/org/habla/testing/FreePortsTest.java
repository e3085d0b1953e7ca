package org.habla.testing;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The free ports tests take: a port handed out once is not handed out again in this JVM, so a broker started on "a
 * free port" after a daemon's five never lands on one of the five (one suite run in five beside busy processes).
 */
class FreePortsTest {

    @Test
    void aPortIsHandedOutOnceWhateverTheKernelGivesTheNextBindOfPortZero() throws Exception {
        Set<Integer> seen = new HashSet<>();
        for (int i = 0; i < 300; i++) {
            int[] five = DaemonProcess.freePorts(5);
            for (int p : five) {
                assertThat(seen.add(p)).as("port %d handed out twice (call %d)", p, i + 1).isTrue();
            }
            assertThat(seen.add(DaemonProcess.freePorts(1)[0])).as("the single port after call %d", i + 1).isTrue();
        }
    }
}
