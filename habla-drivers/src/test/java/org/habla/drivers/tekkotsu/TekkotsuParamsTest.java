package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.habla.config.ParamsJson;
import org.junit.jupiter.api.Test;

class TekkotsuParamsTest {

    private final ObjectMapper json = new ObjectMapper()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES);

    @Test
    void theDefaultsAreTheReferencePortsAndSpeeds() {
        TekkotsuParams p = TekkotsuParams.defaults();

        assertThat(p.worldStatePort()).isEqualTo(10_031);
        assertThat(p.walkPort()).isEqualTo(10_050);
        assertThat(p.headPort()).isEqualTo(10_052);
        assertThat(p.eStopPort()).isEqualTo(10_053);
        assertThat(p.microphonePort()).isEqualTo(10_070);
        assertThat(p.speakerPort()).isEqualTo(10_071);
        assertThat(p.cameraPort()).isEqualTo(10_011);
        assertThat(p.controllerPort()).isEqualTo(10_020);
        assertThat(p.maxForwardMps()).isEqualTo(0.18);
        assertThat(p.maxStrafeMps()).isEqualTo(0.14);
        assertThat(p.maxRotateRadps()).isEqualTo(1.8);
        assertThat(p.walkResendMs()).isEqualTo(1_000);
        assertThat(p.releaseEStop()).isTrue();
        assertThat(p.startServers()).containsExactly("World State Serializer", "Walk Remote Control",
                "WalkController", "Head Remote Control", "HeadController", "Microphone Server", "Speaker Server",
                "Raw Cam Server", "RawCam");
    }

    @Test
    void theParamsBindFromJsonAndTheDefaultServersFollowTheOpenedConnections() throws Exception {
        TekkotsuParams p = ParamsJson.of(TekkotsuParams.class, """
                {"camera": false, "microphone": false, "speaker": false, "head": false, "walkPort": 20050,
                 "maxForwardMps": 0.3}""");

        assertThat(p.walkPort()).isEqualTo(20_050);
        assertThat(p.maxForwardMps()).isEqualTo(0.3);
        assertThat(p.startServers()).containsExactly("World State Serializer", "Walk Remote Control",
                "WalkController");
    }

    @Test
    void anUnknownKeyIsAnError() {
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"walkport\": 1}"))
                .hasMessageContaining("$.params.walkport: unknown parameter 'walkport'");
    }

    @Test
    void badValuesAreRejectedNamingTheParameter() {
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"cameraPort\": 70000}"))
                .hasMessageContaining("$.params.cameraPort: must be within [1, 65535], was 70000");
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"walkResendMs\": 3000}"))
                .hasMessageContaining("$.params.walkResendMs: must be within [100, 2500], was 3000");
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"maxStrafeMps\": -1}"))
                .hasMessageContaining("$.params.maxStrafeMps: must be greater than 0, was -1");
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"cameraSkip\": 5}"))
                .hasMessageContaining("$.params.cameraSkip: must be within [0, 4], was 5");
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"startServers\": [\"a\\\"b\"]}"))
                .hasMessageContaining("startServers entry");
    }

    @Test
    void twoOpenServersOnOnePortAreAnErrorButAClosedOneMayShareIt() throws Exception {
        assertThatThrownBy(() -> ParamsJson.of(TekkotsuParams.class, "{\"headPort\": 10050}"))
                .hasMessageContaining("headPort and walkPort are both 10050");

        TekkotsuParams p = ParamsJson.of(TekkotsuParams.class, "{\"head\": false, \"headPort\": 10050}");
        assertThat(p.head()).isFalse();
    }
}
