package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.databind.exc.ValueInstantiationException;
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
        TekkotsuParams p = json.readValue("""
                {"camera": false, "microphone": false, "speaker": false, "head": false, "walkPort": 20050,
                 "maxForwardMps": 0.3}""", TekkotsuParams.class);

        assertThat(p.walkPort()).isEqualTo(20_050);
        assertThat(p.maxForwardMps()).isEqualTo(0.3);
        assertThat(p.startServers()).containsExactly("World State Serializer", "Walk Remote Control",
                "WalkController");
    }

    @Test
    void anUnknownKeyIsAnError() {
        assertThatThrownBy(() -> json.readValue("{\"walkport\": 1}", TekkotsuParams.class))
                .isInstanceOf(UnrecognizedPropertyException.class);
    }

    @Test
    void badValuesAreRejectedNamingTheParameter() {
        assertThatThrownBy(() -> json.readValue("{\"cameraPort\": 70000}", TekkotsuParams.class))
                .isInstanceOf(ValueInstantiationException.class).hasMessageContaining("cameraPort must be in 1..65535");
        assertThatThrownBy(() -> json.readValue("{\"walkResendMs\": 3000}", TekkotsuParams.class))
                .hasMessageContaining("walkResendMs must be in 100..2500");
        assertThatThrownBy(() -> json.readValue("{\"maxStrafeMps\": -1}", TekkotsuParams.class))
                .hasMessageContaining("maxStrafeMps must be a positive number");
        assertThatThrownBy(() -> json.readValue("{\"cameraSkip\": 5}", TekkotsuParams.class))
                .hasMessageContaining("cameraSkip must be in 0..4");
        assertThatThrownBy(() -> json.readValue("{\"startServers\": [\"a\\\"b\"]}", TekkotsuParams.class))
                .hasMessageContaining("startServers entry");
    }

    @Test
    void twoOpenServersOnOnePortAreAnErrorButAClosedOneMayShareIt() throws Exception {
        assertThatThrownBy(() -> json.readValue("{\"headPort\": 10050}", TekkotsuParams.class))
                .hasMessageContaining("headPort and walkPort are both 10050");

        TekkotsuParams p = json.readValue("{\"head\": false, \"headPort\": 10050}", TekkotsuParams.class);
        assertThat(p.head()).isFalse();
    }
}
