package org.habla.methods.motion;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class MovementSafetyTest {

    private static RecordValue nearest(double aheadM, double behindM) {
        return RecordValue.builder().put("distanceM", Math.min(aheadM, behindM)).put("angleRad", 0.0)
                .put("aheadM", aheadM).put("behindM", behindM).put("valid", true).build();
    }

    private static MethodHarness safety() {
        return MethodHarness.started("safety", new MovementSafety(MovementSafetyParams.defaults()));
    }

    @Test
    void aClearPathLetsTheMotionThrough() {
        MethodHarness h = safety();
        h.push("nearest", nearest(2.0, 2.0)).push("motion", VectorValue.of(0.2, 0.1));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0.2, 0.1));
        assertThat(h.values("veto")).isEmpty();
    }

    @Test
    void forwardIsVetoedNearAnObstacleAheadButTurningAndBackingAreNot() {
        MethodHarness h = safety();
        h.push("nearest", nearest(0.2, 3.0)).push("motion", VectorValue.of(0.2, 0.4));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0.4));
        assertThat(((TextValue) h.last("veto")).text()).contains("forward motion vetoed", "0.20 m ahead");
        h.push("motion", VectorValue.of(-0.1, 0));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(-0.1, 0));
        h.push("nearest", nearest(0.2, 0.1));
        assertThat(h.last("motion")).as("the held backward motion meets a wall behind").isEqualTo(VectorValue.of(0, 0));
        assertThat(((TextValue) h.last("veto")).text()).contains("backward motion vetoed");
    }

    @Test
    void aHeldMotionStopsWhenAnObstacleComesCloseAndGoesOnWhenItIsGone() {
        MethodHarness h = safety();
        h.push("nearest", nearest(1.0, 3.0)).push("motion", VectorValue.of(0.2, 0));
        h.push("nearest", nearest(0.8, 3.0)).push("nearest", nearest(0.25, 3.0)).push("nearest", nearest(0.24, 3.0));
        assertThat(h.values("motion")).containsExactly(VectorValue.of(0.2, 0), VectorValue.of(0, 0));
        assertThat(h.values("veto")).as("one veto line per veto").hasSize(1);
        h.push("nearest", nearest(0.5, 3.0));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0.2, 0));
    }

    @Test
    void withoutAheadAndBehindTheNearestBearingDecidesAndWithoutRangeDataTranslationIsVetoed() {
        MethodHarness h = safety();
        h.push("motion", VectorValue.of(0.2, 0));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        assertThat(((TextValue) h.last("veto")).text()).contains("no fresh range data");
        h.push("nearest", RecordValue.builder().put("distanceM", 0.1).put("angleRad", Math.PI / 2).build());
        assertThat(h.last("motion")).as("an obstacle to the side does not stop forward motion")
                .isEqualTo(VectorValue.of(0.2, 0));
        h.push("nearest", RecordValue.builder().put("distanceM", 0.1).put("angleRad", -0.5).build());
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        h.push("nearest", RecordValue.builder().put("distanceM", 2.0).put("angleRad", 0.0).build());
        h.advanceMillis(1200);
        assertThat(h.last("motion")).as("range data went silent").isEqualTo(VectorValue.of(0, 0));
    }

    @Test
    void afterAMotionStopTheOldMotionNeverComesBackAndTheSameOneAskedAgainGoesOut() {
        MethodHarness h = safety();
        h.push("nearest", nearest(1.0, 3.0)).push("motion", VectorValue.of(0.2, 0)).clear();
        h.motionStopped();
        h.push("nearest", nearest(0.2, 3.0)).push("nearest", nearest(1.0, 3.0)).advanceMillis(500);
        assertThat(h.values("motion")).as("nothing wanted since the stop").isEmpty();
        h.push("nearest", nearest(1.0, 3.0)).push("motion", VectorValue.of(0.2, 0));
        assertThat(h.values("motion")).containsExactly(VectorValue.of(0.2, 0));
    }

    @Test
    void everyVetoedMotionAskedForIsToldToControlWithTheReasonAndTheLimit() {
        MethodHarness h = safety();
        h.push("nearest", nearest(0.2, 3.0)).push("motion", VectorValue.of(0.25, 0), 1_700_000_000_123_456L);
        assertThat(h.notices()).singleElement().satisfies(n -> {
            assertThat(n.notice()).isEqualTo("veto");
            assertThat(n.methodId()).isEqualTo("safety");
            assertThat(n.sourceMicros()).as("the time of the motion asked for").isEqualTo(1_700_000_000_123_456L);
            assertThat(n.message()).isEqualTo("forward motion vetoed: obstacle 0.20 m ahead (stop distance 0.30 m)");
            assertThat(n.detail().get("reason").asText()).isEqualTo("obstacle_ahead");
            assertThat(n.detail().number("obstacleM")).isEqualTo(0.2);
            assertThat(n.detail().number("stopDistanceM")).isEqualTo(0.3);
            assertThat(n.detail().number("askedMps")).isEqualTo(0.25);
        });
        h.push("motion", VectorValue.of(0.25, 0));
        assertThat(h.notices()).as("asked again, told again").hasSize(2);
        h.push("motion", VectorValue.of(0, 0.5));
        assertThat(h.notices()).as("turning is not vetoed").hasSize(2);
    }

    @Test
    void aHeldMotionThatMeetsAnObstacleIsToldOnceAndMissingRangeDataNamesItsLimit() {
        MethodHarness h = safety();
        h.push("nearest", nearest(1.0, 3.0)).push("motion", VectorValue.of(-0.2, 0));
        assertThat(h.notices()).isEmpty();
        h.push("nearest", nearest(1.0, 0.2)).push("nearest", nearest(1.0, 0.1));
        assertThat(h.notices()).singleElement().satisfies(n ->
                assertThat(n.detail().get("reason").asText()).isEqualTo("obstacle_behind"));
        h.clear().push("nearest", nearest(1.0, 3.0)).advanceMillis(1_500);
        assertThat(h.notices()).singleElement().satisfies(n -> {
            assertThat(n.detail().get("reason").asText()).isEqualTo("no_range_data");
            assertThat(n.detail().number("maxAgeMs")).isEqualTo(1000);
            assertThat(n.message()).contains("none in the last 1000 ms");
        });
    }

    @Test
    void theLimitsInputScalesTheMotion() {
        MethodHarness h = safety();
        h.push("limits", RecordValue.builder().put("maxVelMps", 0.1).build());
        h.push("nearest", nearest(5, 5)).push("motion", VectorValue.of(0.4, 0.4));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0.1, 0.1));
    }

    @Test
    void aVetosDetailIsWrittenForControlClientsFieldByFieldAsTheProtocolDocumentsIt() {
        MethodHarness h = safety();
        h.push("motion", VectorValue.of(0.2, 0.1));
        h.push("nearest", nearest(0.25, 3.0)).push("motion", VectorValue.of(0.5, 0));
        h.advanceMillis(1_500).push("motion", VectorValue.of(-0.1, -0.5));
        assertThat(h.notices()).extracting(n -> n.detail().jsonView().toString()).containsExactly(
                "{\"askedMps\":0.2,\"askedRadps\":0.1,\"reason\":\"no_range_data\",\"maxAgeMs\":1000}",
                "{\"askedMps\":0.5,\"askedRadps\":0.0,\"reason\":\"obstacle_ahead\",\"obstacleM\":0.25,"
                        + "\"stopDistanceM\":0.3}",
                "{\"askedMps\":-0.1,\"askedRadps\":-0.5,\"reason\":\"no_range_data\",\"maxAgeMs\":1000,"
                        + "\"ageMs\":1500}");
        assertThat(h.notices()).extracting(n -> n.detail().carriesForm()).as("typed until a socket writes it")
                .containsExactly(new VetoDetail.NoRangeData(0.2, 0.1, 1000, null),
                        new VetoDetail.Obstacle(0.5, 0, 0.25, 0.3), new VetoDetail.NoRangeData(-0.1, -0.5, 1000, 1500L));
    }
}
