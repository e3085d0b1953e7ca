package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class DistanceAngleTest {

    private static RecordValue record(double d, double a, boolean seen) {
        return RecordValue.builder().put("distanceM", d).put("angleRad", a).put("seen", seen).build();
    }

    private static RecordValue position(double d, double a, boolean seen) {
        return RecordValue.builder().put("xM", 1.0).put("yM", 0.0).put("distanceM", d).put("angleRad", a)
                .put("seen", seen).build();
    }

    @Test
    void emitsAtTheSteadyRateFromAPositionInput() {
        MethodHarness h = MethodHarness.started("da", new DistanceAngle(DistanceAngleParams.defaults()));
        h.advanceMillis(500);
        assertThat(h.values("distance_angle")).as("nothing before the first input").isEmpty();
        h.push("position", position(1.2, 0.3, true)).advanceMillis(1000);
        List<Payload> out = h.values("distance_angle");
        assertThat(out).hasSize(10).allMatch(p -> p.equals(record(1.2, 0.3, true)));
    }

    @Test
    void anUnseenTargetKeepsTheLastSightingWithSeenFalse() {
        MethodHarness h = MethodHarness.started("da", new DistanceAngle(DistanceAngleParams.defaults()));
        h.push("position", position(0.8, -0.5, true)).advanceMillis(100);
        h.push("position", position(9, 9, false)).advanceMillis(100);
        assertThat(h.last("distance_angle")).isEqualTo(record(0.8, -0.5, false));
        h.push("position", position(0.7, -0.4, true)).advanceMillis(100);
        assertThat(h.last("distance_angle")).isEqualTo(record(0.7, -0.4, true));
    }

    @Test
    void silenceLongerThanLostAfterMsMeansNotSeen() {
        MethodHarness h = MethodHarness.started("da", new DistanceAngle(ParamsJson.of(DistanceAngleParams.class, "{\"rateHz\": 5.0, \"lostAfterMs\": 500}")));
        h.push("nearest", RecordValue.builder().put("distanceM", 0.6).put("angleRad", 0.1).put("xM", 0.6)
                .put("yM", 0.06).put("sensor", 3).build());
        h.advanceMillis(400);
        assertThat(h.last("distance_angle")).isEqualTo(record(0.6, 0.1, true));
        h.advanceMillis(400);
        assertThat(h.last("distance_angle")).isEqualTo(record(0.6, 0.1, false));
        assertThat(h.values("distance_angle")).hasSize(4);
    }

    @Test
    void aNearestRecordMarkedInvalidIsNotASightingAndGarbageIsIgnored() {
        DistanceAngle m = new DistanceAngle(DistanceAngleParams.defaults());
        MethodHarness h = MethodHarness.started("da", m);
        h.push("nearest", RecordValue.builder().put("distanceM", 5.0).put("angleRad", 0.0).put("valid", false).build());
        h.advanceMillis(100);
        assertThat(h.last("distance_angle")).isEqualTo(record(0, 0, false));
        h.push("nearest", RecordValue.builder().put("distanceM", "far").put("angleRad", 0.0).build());
        h.push("nearest", RecordValue.builder().put("distanceM", -1.0).put("angleRad", 0.0).build());
        h.advanceMillis(100);
        assertThat(h.last("distance_angle")).isEqualTo(record(0, 0, false));
        assertThat(m.malformed()).isEqualTo(2);
    }

    @Test
    void theRateIsChecked() {
        assertThatThrownBy(() -> ParamsJson.of(DistanceAngleParams.class, "{\"rateHz\": 0.0}")).hasMessageContaining("rateHz");
    }
}
