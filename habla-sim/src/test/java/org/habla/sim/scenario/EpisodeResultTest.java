package org.habla.sim.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import org.junit.jupiter.api.Test;

class EpisodeResultTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void anEpisodeRoundTripsThroughJson() throws Exception {
        EpisodeResult e = new EpisodeResult(4, List.of(new PhaseObedience("teaching", 12, 9)),
                List.of(new DistanceSample(0, 2.0), new DistanceSample(0.1, 1.95)), true, 31.5);
        String text = JSON.writeValueAsString(e.toJson());

        assertThat(EpisodeResult.fromJson(JSON.readTree(text))).isEqualTo(e);
        assertThat(text).contains("\"distance\":[[0.0,2.0],[0.1,1.95]]");
    }

    @Test
    void badEpisodesAreRefusedSayingWhy() throws Exception {
        assertThatThrownBy(() -> new PhaseObedience("teaching", 3, 4)).hasMessageContaining("obeyed 4 of 3");
        assertThatThrownBy(() -> new EpisodeResult(1, List.of(), List.of(), true, Double.NaN))
                .hasMessageContaining("time to reach");
        assertThatThrownBy(() -> new EpisodeResult(1, List.of(), List.of(new DistanceSample(2, 1),
                new DistanceSample(1, 1)), false, Double.NaN)).hasMessageContaining("back in time");
        assertThatThrownBy(() -> new DistanceSample(0, -1)).hasMessageContaining("distance");
        assertThatThrownBy(() -> EpisodeResult.fromJson(JSON.readTree(
                "{\"episode\":1,\"obedience\":[],\"distance\":[[0,\"far\"]],\"reached\":false}")))
                .hasMessageContaining("[seconds, metres]");
        assertThatThrownBy(() -> EpisodeResult.fromJson(JSON.readTree(
                "{\"episode\":1.5,\"obedience\":[],\"distance\":[],\"reached\":false}")))
                .hasMessageContaining("\"episode\" must be a whole number");
    }
}
