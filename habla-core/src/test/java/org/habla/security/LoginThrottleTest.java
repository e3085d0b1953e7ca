package org.habla.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

class LoginThrottleTest {

    private static final long MS = 1_000_000;

    private final AtomicLong now = new AtomicLong(1_000 * MS);
    private final LoginThrottle throttle = new LoginThrottle(now::get);

    @Test
    void anAddressHasABurstOfTriesThenOneEachRefill() {
        for (int i = 0; i < LoginThrottle.BURST; i++) {
            assertThat(throttle.take("10.0.0.99")).as("try %d", i).isZero();
        }
        assertThat(throttle.take("10.0.0.99")).isEqualTo(LoginThrottle.REFILL_MS);
        now.addAndGet(LoginThrottle.REFILL_MS * MS - 1);
        assertThat(throttle.take("10.0.0.99")).as("not quite back").isPositive();
        now.addAndGet(1);
        assertThat(throttle.take("10.0.0.99")).isZero();
        assertThat(throttle.take("10.0.0.99")).isPositive();
    }

    @Test
    void anotherAddressIsNotHeldBackAndASuccessGivesItsTryBack() {
        for (int i = 0; i < LoginThrottle.BURST; i++) {
            throttle.take("10.0.0.99");
        }
        assertThat(throttle.take("10.0.0.30")).isZero();
        throttle.giveBack("10.0.0.30");
        for (int i = 0; i < LoginThrottle.BURST; i++) {
            assertThat(throttle.take("10.0.0.30")).as("try %d of the good client's address", i).isZero();
        }
        assertThat(throttle.take("10.0.0.99")).isPositive();
    }

    @Test
    void triesComeBackOnlyUpToTheBurst() {
        throttle.take("10.0.0.99");
        now.addAndGet(3_600_000 * MS);
        for (int i = 0; i < LoginThrottle.BURST; i++) {
            assertThat(throttle.take("10.0.0.99")).isZero();
        }
        assertThat(throttle.take("10.0.0.99")).isPositive();
    }

    @Test
    void itRemembersABoundedNumberOfAddresses() {
        for (int i = 0; i <= LoginThrottle.MAX_ADDRESSES; i++) {
            for (int t = 0; t <= LoginThrottle.BURST; t++) {
                throttle.take("10." + (i >> 16) + "." + (i >> 8 & 255) + "." + (i & 255));
            }
        }
        assertThat(throttle.take("10.0.0.0")).as("the address seen least recently was forgotten").isZero();
        assertThat(throttle.take("10.0.16.0")).as("the one seen last is remembered").isPositive();
    }
}
