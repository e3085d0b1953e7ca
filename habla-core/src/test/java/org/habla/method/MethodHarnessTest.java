package org.habla.method;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

/**
 * What the harness does when the method under test throws: the test fails with the method's exception, unless the
 * test said it expects the failure.
 */
class MethodHarnessTest {

    /** Emits a record's {@code distanceM}; a record without it makes {@link RecordValue#number} throw. */
    static final class Distance extends ProcessingMethod {
        static final InputPort<RecordValue> NEAREST = InputPort.of("nearest", RecordValue.class, Delivery.queue(4));
        static final OutputPort<NumberValue> METRES = OutputPort.of("metres", NumberValue.class,
                Shape.number("m", "the distance"));

        private final Output<NumberValue> metres = output(METRES);
        private final boolean failAtStart;
        private final boolean failOnTick;

        Distance(boolean failAtStart, boolean failOnTick) {
            this.failAtStart = failAtStart;
            this.failOnTick = failOnTick;
            input(NEAREST, this::onNearest);
            tickEvery(Duration.ofMillis(100));
        }

        private void onNearest(RecordValue obstacle, Sample s) {
            emit(metres, new NumberValue(obstacle.number("distanceM")));
        }

        @Override
        protected void onStart() {
            if (failAtStart) {
                throw new IllegalStateException("no model file");
            }
        }

        @Override
        protected void onTick(long nowMicros) {
            if (failOnTick) {
                throw new IllegalStateException("tick went wrong");
            }
        }

        void slowWork() {
            background("load", () -> {
                throw new java.io.IOException("model not found");
            }, v -> { });
        }
    }

    private static RecordValue without(String field) {
        return RecordValue.builder().put("other" + field, 1.0).build();
    }

    @Test
    void aHandlerThatThrowsFailsTheTestWithTheMethodsException() {
        MethodHarness h = MethodHarness.started("near", new Distance(false, false));
        h.push("nearest", RecordValue.builder().put("distanceM", 0.4).build());

        assertThatThrownBy(() -> h.push("nearest", without("distanceM")))
                .isInstanceOf(AssertionError.class)
                .hasMessageContaining("method near (Distance) failed to handle a sample of nearest")
                .hasMessageContaining("record has no number field 'distanceM'")
                .hasMessageContaining("expectFailure()")
                .hasCauseInstanceOf(IllegalArgumentException.class);
        assertThat(h.state()).isEqualTo(MethodState.FAILED);
    }

    @Test
    void aTestThatExpectsTheFailureReadsItFromTheStateAndTheReason() {
        MethodHarness h = MethodHarness.started("near", new Distance(false, false)).expectFailure();
        h.push("nearest", without("distanceM"));

        assertThat(h.state()).isEqualTo(MethodState.FAILED);
        assertThat(h.failure()).contains("failed to handle a sample of nearest", "'distanceM'");
        assertThat(h.values("metres")).isEmpty();
    }

    @Test
    void aStartThatThrowsFailsStartedButNotAStartExpectedToFail() {
        assertThatThrownBy(() -> MethodHarness.started("near", new Distance(true, false)))
                .isInstanceOf(AssertionError.class).hasMessageContaining("failed to start")
                .hasRootCauseMessage("no model file");

        MethodHarness h = MethodHarness.of("near", new Distance(true, false)).expectFailure().start();
        assertThat(h.state()).isEqualTo(MethodState.FAILED);
    }

    @Test
    void aTickThatThrowsFailsTheAdvanceThatRanIt() {
        MethodHarness h = MethodHarness.started("near", new Distance(false, true));
        assertThatThrownBy(() -> h.advanceMillis(250)).isInstanceOf(AssertionError.class)
                .hasMessageContaining("failed to tick").hasRootCauseMessage("tick went wrong");
    }

    @Test
    void backgroundWorkThatThrowsFailsTheRunThatFinishedIt() {
        Distance d = new Distance(false, false);
        MethodHarness h = MethodHarness.started("near", d);
        d.slowWork();
        assertThatThrownBy(h::runBackground).isInstanceOf(AssertionError.class)
                .hasMessageContaining("failed to load").hasRootCauseMessage("model not found");
    }
}
