package org.example.habla;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class ThresholdTest {

    private static RecordValue obstacleAt(double distanceM) {
        return RecordValue.builder().put("distanceM", distanceM).build();
    }

    @Test
    void theLabelChangesOnlyWhenTheDistanceCrossesTheFarSideOfTheBand() {
        MethodHarness h = MethodHarness.started("near", new Threshold(ParamsJson.defaults(ThresholdParams.class)));

        for (double d : new double[] {1.0, 0.7, 0.4, 0.6, 0.9}) {
            h.push("nearest", obstacleAt(d));
        }

        assertThat(h.values("label")).containsExactly(new TextValue("far"), new TextValue("near"),
                new TextValue("far"));
    }

    @Test
    void paramsWithTheBandUpsideDownAreRefusedNamingBoth() {
        assertThatThrownBy(() -> new ThresholdParams(0.9, 0.3))
                .hasMessageContaining("nearM (0.9)").hasMessageContaining("farM (0.3)");
    }
}
