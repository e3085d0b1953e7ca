package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor.Direction;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.PayloadKind;
import org.junit.jupiter.api.Test;

class TekkotsuDriverTest {

    private static ChannelDescriptor channel(Driver d, String name, Direction direction) {
        return d.channels().stream().filter(c -> c.name().equals(name) && c.direction() == direction).findFirst()
                .orElseThrow();
    }

    @Test
    void theTypeIsFoundByNameThroughDiscovery() {
        DriverProvider<?> provider = PluginRegistry.discover().driver("tekkotsu").orElseThrow();

        assertThat(provider).isInstanceOf(TekkotsuDriverProvider.class);
        assertThat(provider.paramsType()).isEqualTo(TekkotsuParams.class);
    }

    @Test
    void allServersOpenByDefaultWithTheContractsChannels() {
        Driver d = new TekkotsuDriverProvider().create(InterfaceAddress.parse("aibo.local"), TekkotsuParams.defaults());

        assertThat(d.connections()).extracting(Connection::name).containsExactly("worldstate", "microphone", "camera",
                "walk", "head", "speaker", "estop", "controller");
        assertThat(d.connections()).extracting(Connection::port).containsExactly(10_031, 10_070, 10_011, 10_050,
                10_052, 10_071, 10_053, 10_020);
        assertThat(channel(d, "ir", Direction.READING).kind()).isEqualTo(PayloadKind.VECTOR);
        assertThat(channel(d, "ir", Direction.READING).unit()).isEqualTo("m");
        assertThat(channel(d, "buttons", Direction.READING).kind()).isEqualTo(PayloadKind.RECORD);
        assertThat(channel(d, "joints", Direction.READING).unit()).isEqualTo("rad");
        assertThat(channel(d, "head-pose", Direction.READING).kind()).isEqualTo(PayloadKind.RECORD);
        assertThat(channel(d, "accel", Direction.READING).kind()).isEqualTo(PayloadKind.VECTOR);
        assertThat(channel(d, "audio", Direction.READING).kind()).isEqualTo(PayloadKind.AUDIO);
        assertThat(channel(d, "camera", Direction.READING).kind()).isEqualTo(PayloadKind.IMAGE);
        ChannelDescriptor walk = channel(d, "walk", Direction.COMMAND);
        assertThat(walk.motion()).isTrue();
        assertThat(walk.kind()).isEqualTo(PayloadKind.VECTOR);
        assertThat(channel(d, "head", Direction.COMMAND).kind()).isEqualTo(PayloadKind.VECTOR);
        assertThat(channel(d, "speaker", Direction.COMMAND).kind()).isEqualTo(PayloadKind.AUDIO);
        assertThat(d.channels()).noneMatch(c -> c.name().equals(Driver.LINK_CHANNEL.name()));
        assertThat(d.connections().stream().filter(c -> c.name().equals("walk")).findFirst().orElseThrow()
                .commandChannels()).containsExactly("walk");
    }

    @Test
    void theMetadataCarriesTheRobotsFacts() {
        Driver d = new TekkotsuDriver(TekkotsuParams.defaults());

        var camera = channel(d, "camera", Direction.READING).metadata();
        assertThat(camera.get("hfovRad").asDouble()).isCloseTo(0.9931, org.assertj.core.data.Offset.offset(1e-4));
        assertThat(camera.get("vfovRad").asDouble()).isCloseTo(0.7889, org.assertj.core.data.Offset.offset(1e-4));
        assertThat(camera.get("width").asInt()).isEqualTo(104);
        assertThat(camera.get("height").asInt()).isEqualTo(80);
        assertThat(camera.get("heightM").asDouble()).isEqualTo(0.2);
        var ir = channel(d, "ir", Direction.READING).metadata();
        assertThat(ir.get("poses")).hasSize(3);
        assertThat(ir.get("poses").get(2).get("name").asText()).isEqualTo("chest");
        assertThat(ir.get("maxRangeM").asDouble()).isEqualTo(1.5);
        assertThat(channel(d, "joints", Direction.READING).metadata().get("names")).hasSize(18);
        assertThat(channel(d, "buttons", Direction.READING).metadata().get("names").get(5).asText())
                .isEqualTo("headTouch");
    }

    @Test
    void onlyTheControllerIsOptionalSoARobotWithoutOneIsUpWhileItsServersStream() {
        Driver d = new TekkotsuDriver(TekkotsuParams.defaults());
        assertThat(d.connections()).filteredOn(Connection::optional).extracting(Connection::name)
                .containsExactly("controller");
        assertThat(d.connections()).filteredOn(c -> !c.optional()).extracting(Connection::name)
                .containsExactlyInAnyOrder("worldstate", "microphone", "camera", "walk", "head", "speaker", "estop");
    }

    @Test
    void aServerSwitchedOffOffersNeitherItsConnectionNorItsChannels() throws Exception {
        TekkotsuParams p = ParamsJson.of(TekkotsuParams.class, "{\"head\": false, \"microphone\": false, \"camera\": false}");
        Driver d = new TekkotsuDriver(p);

        assertThat(d.connections()).extracting(Connection::name).containsExactly("worldstate", "walk", "speaker",
                "estop", "controller");
        List<String> names = d.channels().stream().map(c -> c.name() + "/" + c.direction()).toList();
        assertThat(names).doesNotContain("camera/READING", "audio/READING", "head/COMMAND")
                .contains("head-pose/READING", "walk/COMMAND", "speaker/COMMAND");
        assertThat(p.startServers()).doesNotContain("Raw Cam Server", "Microphone Server", "Head Remote Control");
    }
}
