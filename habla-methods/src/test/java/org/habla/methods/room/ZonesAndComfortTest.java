package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class ZonesAndComfortTest {

    @Test
    void occupancyListsTheOccupiedZonesAndCountsThem() {
        MethodHarness h = MethodHarness.started("occupancy",
                new Occupancy(ParamsJson.of(Occupancy.Params.class, "{\"zones\": [\"desk\", \"sofa\", \"door\"], \"periodMs\": 0}")));
        h.push("sofa", new NumberValue(1)).push("desk", new NumberValue(1)).push("sofa", new NumberValue(0));
        RecordValue last = (RecordValue) h.last("occupancy");
        assertThat(last.get("zones").toString()).isEqualTo("{\"desk\":1,\"sofa\":0,\"door\":0}");
        assertThat(last.get("occupied").toString()).isEqualTo("[\"desk\"]");
        assertThat(last.number("count")).isEqualTo(1);
        assertThat(h.values("occupancy")).hasSize(3);
    }

    @Test
    void occupancyIsSentAgainEveryPeriodOnceAZoneWasHeard() {
        MethodHarness h = MethodHarness.started("occupancy", new Occupancy(ParamsJson.of(Occupancy.Params.class, "{\"zones\": [\"desk\"], \"periodMs\": 500}")));
        h.advanceMillis(2_000);
        assertThat(h.values("occupancy")).as("nothing heard, nothing said").isEmpty();
        h.push("desk", new NumberValue(1)).advanceMillis(1_050);
        assertThat(h.values("occupancy")).hasSize(3);
        assertThat(h.values("occupancy").get(2)).isEqualTo(h.values("occupancy").get(0));
    }

    @Test
    void comfortScoresTheReadingsHeardAndNamesWhatIsWrong() {
        MethodHarness h = MethodHarness.started("comfort", new Comfort(ParamsJson.of(Comfort.Params.class, "{}")));
        h.push("climate", RecordValue.builder().put("temperatureC", 18.0).put("humidityPct", 45.0).build());
        RecordValue c = (RecordValue) h.last("comfort");
        assertThat(c.number("score")).isEqualTo(0.5);
        assertThat(c.get("complaints").toString()).isEqualTo("[\"cold\"]");
        h.push("lux", new NumberValue(500)).push("sound", new NumberValue(-10));
        c = (RecordValue) h.last("comfort");
        assertThat(c.number("score")).isEqualTo(0.5);
        assertThat(c.get("complaints").toString()).isEqualTo("[\"cold\",\"noisy\"]");
    }

    @Test
    void lightLevelsListEveryZoneHeardAndTheDarkOnes() {
        MethodHarness h = MethodHarness.started("light",
                new LightLevels(ParamsJson.of(LightLevels.Params.class, "{\"zones\": [\"desk\", \"sofa\", \"kitchen\"], \"darkLux\": 150.0}")));
        h.push("sofa", new NumberValue(90)).push("desk", new NumberValue(400));
        RecordValue last = (RecordValue) h.last("light");
        assertThat(last.get("lux").toString()).isEqualTo("{\"desk\":400.0,\"sofa\":90.0}");
        assertThat(last.get("dark").toString()).isEqualTo("[\"sofa\"]");
    }
}
