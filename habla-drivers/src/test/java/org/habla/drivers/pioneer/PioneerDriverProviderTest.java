package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.PayloadKind;
import org.junit.jupiter.api.Test;

class PioneerDriverProviderTest {

    @SuppressWarnings("unchecked")
    private static Driver create(String address, String paramsJson) throws Exception {
        DriverProvider<PioneerParams> provider = (DriverProvider<PioneerParams>) PluginRegistry.discover().driver("pioneer")
                .orElseThrow();
        return provider.create(InterfaceAddress.parse(address), ParamsJson.of(provider.paramsType(), paramsJson));
    }

    @Test
    void thePioneerTypeIsFoundByNameThroughDiscovery() {
        DriverProvider<?> provider = PluginRegistry.discover().driver("pioneer").orElseThrow();
        assertThat(provider).isInstanceOf(PioneerDriverProvider.class);
        assertThat(provider.paramsType()).isEqualTo(PioneerParams.class);
    }

    @Test
    void theChannelsAreTheContractsNamesKindsAndDirections() throws Exception {
        Map<String, ChannelDescriptor> ch = create("127.0.0.1", "{}").channels().stream()
                .collect(Collectors.toMap(ChannelDescriptor::name, Function.identity()));
        assertThat(ch.keySet()).containsExactlyInAnyOrder("sonar", "odometry", "battery", "bumpers", "stall", "status",
                "motion", "sonar-power");
        assertThat(ch.get("sonar").kind()).isEqualTo(PayloadKind.VECTOR);
        assertThat(ch.get("sonar").unit()).isEqualTo("m");
        assertThat(ch.get("odometry").kind()).isEqualTo(PayloadKind.RECORD);
        assertThat(ch.get("battery").kind()).isEqualTo(PayloadKind.NUMBER);
        assertThat(ch.get("battery").unit()).isEqualTo("V");
        assertThat(ch.get("motion").direction()).isEqualTo(ChannelDescriptor.Direction.COMMAND);
        assertThat(ch.get("motion").motion()).isTrue();
        assertThat(ch.get("sonar-power").motion()).isFalse();
        assertThat(ch.get("sonar-power").kind()).isEqualTo(PayloadKind.NUMBER);
    }

    @Test
    void theSonarMetadataCarriesTheSixteenP2dxPosesInMetresAndRadians() throws Exception {
        JsonNode meta = create("127.0.0.1", "{}").channels().get(0).metadata();
        assertThat(meta.path("poses")).hasSize(16);
        assertThat(meta.path("poses").get(0).path("xM").asDouble()).isCloseTo(0.069, within(1e-9));
        assertThat(meta.path("poses").get(0).path("yM").asDouble()).isCloseTo(0.136, within(1e-9));
        assertThat(meta.path("poses").get(0).path("thetaRad").asDouble()).isCloseTo(Math.PI / 2, within(1e-9));
        assertThat(meta.path("poses").get(11).path("thetaRad").asDouble()).isCloseTo(Math.toRadians(-170), within(1e-9));
        assertThat(meta.path("maxRangeM").asDouble()).isEqualTo(5.0);
        assertThat(meta.path("minRangeM").asDouble()).isEqualTo(0.1);
        assertThat(meta.path("beamWidthRad").asDouble()).isCloseTo(Math.toRadians(30), within(1e-9));
    }

    @Test
    void theGeometryIsOnOdometryAndStatusInSiUnits() throws Exception {
        Driver d = create("127.0.0.1", "{\"maxVelMps\": 0.5}");
        for (ChannelDescriptor c : d.channels()) {
            if (c.name().equals("odometry") || c.name().equals("status")) {
                assertThat(c.metadata().path("radiusM").asDouble()).isEqualTo(0.25);
                assertThat(c.metadata().path("maxVelMps").asDouble()).isEqualTo(0.5);
                assertThat(c.metadata().path("maxRotVelRadps").asDouble()).isEqualTo(1.74);
            }
        }
    }

    @Test
    void theConnectionIsOnPort8101UnlessTheAddressNamesAnother() throws Exception {
        assertThat(create("127.0.0.1", "{}").connections()).singleElement().satisfies(c -> {
            assertThat(c.port()).isEqualTo(8101);
            assertThat(c.commandChannels()).containsExactlyInAnyOrder("motion", "sonar-power");
        });
        assertThat(create("127.0.0.1:8102", "{}").connections().get(0).port()).isEqualTo(8102);
    }

    @Test
    void eachConnectionGetsAFreshSession() throws Exception {
        var sessions = create("127.0.0.1", "{}").connections().get(0).sessions();
        assertThat(sessions.get()).isNotSameAs(sessions.get());
    }

    @Test
    void anUnknownParameterIsRefused() {
        assertThatThrownBy(() -> create("127.0.0.1", "{\"maxSpeed\": 1}")).hasMessageContaining("unknown parameter");
    }

    @Test
    void aBadValueIsRefusedNamingTheParameter() {
        assertThatThrownBy(() -> create("127.0.0.1", "{\"keepAlivePeriodMs\": 3000}"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("keepAlivePeriodMs");
        assertThatThrownBy(() -> create("127.0.0.1", "{\"distConvFactor\": -1}"))
                .hasMessageContaining("distConvFactor");
    }

    @Test
    void otherSonarPosesCanBeGivenInParams() throws Exception {
        Driver d = create("127.0.0.1", "{\"sonarPoses\": [{\"xM\": 0.1, \"yM\": 0, \"thetaRad\": 0},"
                + " {\"xM\": -0.1, \"yM\": 0, \"thetaRad\": 3.14159}]}");
        assertThat(d.channels().get(0).metadata().path("poses")).hasSize(2);
    }
}
