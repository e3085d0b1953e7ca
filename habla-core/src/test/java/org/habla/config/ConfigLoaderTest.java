package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import org.habla.driver.InterfaceAddress;
import org.habla.method.Layer;
import org.habla.net.Expose;
import org.habla.net.Limits;
import org.habla.plugin.NoParams;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ConfigLoaderTest {

    private final ConfigLoader loader = new ConfigLoader(TestPlugins.registry());

    static Path resource(String name) throws URISyntaxException {
        return Path.of(ConfigLoaderTest.class.getResource("/configs/" + name).toURI());
    }

    @Test
    void preloadingReadsItsOwnSmallConfigWithoutAnError() {
        org.assertj.core.api.Assertions.assertThatCode(ConfigLoader::preload).doesNotThrowAnyException();
    }

    @Test
    void validConfigLoadsIntoTheExpectedRecords() throws Exception {
        HablaConfig config = loader.load(resource("valid/pioneer-like.json"));

        assertThat(config.system()).isEqualTo("test-robot");
        assertThat(config.limits()).isEqualTo(new Limits(4096, Limits.DEFAULTS.maxBinaryBytes(),
                Limits.DEFAULTS.maxClientsPerPort(), Limits.DEFAULTS.clientQueueSamples()));
        assertThat(config.safety()).isEqualTo(new Safety(500));
        assertThat(config.status()).isEqualTo(new StatusConfig("127.0.0.1", 7199));
        assertThat(config.interfaces()).containsExactly(new InterfaceConfig("robot", "robot-sim",
                new InterfaceAddress("127.0.0.1", OptionalInt.of(8101)), new TestDriver.Params(8),
                new Reconnect(100, 5_000, 3_000, 0)));
        assertThat(config.methods()).extracting(MethodConfig::id)
                .containsExactly("sonar", "nearest", "distance", "action", "safety", "wheels");

        assertThat(config.method("sonar")).contains(new MethodConfig("sonar", "sonar", Layer.SENSORS_ACTUATORS,
                Map.of("ranges", new Source.Channel("robot", "sonar")), Map.of(),
                new TestMethods.SonarParams(4.5, 0.1, List.of(0, 1, 2)), Optional.empty(), Optional.empty()));
        assertThat(config.method("nearest").orElseThrow().params()).isEqualTo(new NoParams());
        assertThat(config.method("distance").orElseThrow().expose())
                .contains(new Expose("distance_angle", "127.0.0.1", 7002));
        MethodConfig action = config.method("action").orElseThrow();
        assertThat(action.inputs()).containsEntry("action", new Source.Control());
        assertThat(action.expose()).contains(new Expose("action", "127.0.0.1", 7004));
        assertThat(action.host()).contains("127.0.0.1:7600");
        MethodConfig wheels = config.method("wheels").orElseThrow();
        assertThat(wheels.inputs()).containsEntry("velocity", new Source.MethodOutput("safety", "velocity"));
        assertThat(wheels.commands()).containsEntry("motion", new ChannelRef("robot", "motion"));
        assertThat(wheels.params()).isEqualTo(new TestMethods.WheelsParams(0.33, TestMethods.WheelsParams.Stop.HARD));
    }

    @Test
    void everySocketLimitIsReadAndBudgetsLeftOutGrowWithTheLargestBlock() throws Exception {
        HablaConfig config = loader.parse("""
                {"system": "s", "limits": {"maxPendingPerPort": 32, "idleTimeoutMs": 0, "frameTimeoutMs": 2500,
                  "evictableIdleMs": 700, "processBlockBudgetBytes": 100000000}}""");
        assertThat(config.limits()).isEqualTo(Limits.DEFAULTS.withCaps(16, 32).withDeadlines(0, 2_500, 700)
                .withBlockBudgets(Limits.SOCKET_BLOCK_BUDGET_BYTES, 100_000_000));
        Limits big = loader.parse("{\"system\": \"s\", \"limits\": {\"maxBinaryBytes\": 100000000}}").limits();
        assertThat(big.socketBlockBudgetBytes()).isEqualTo(100_000_000);
        assertThat(big.processBlockBudgetBytes()).isEqualTo(100_000_000);
    }

    @Test
    void absentSectionsTakeTheirDefaults() throws Exception {
        HablaConfig config = loader.parse("{\"system\": \"bare\"}");

        assertThat(config).isEqualTo(new HablaConfig("bare", Limits.DEFAULTS, Safety.DEFAULTS,
                StatusConfig.DEFAULTS, List.of(), List.of()));
    }

    @Test
    void interfaceWithoutParamsOrReconnectGetsDefaults() throws Exception {
        HablaConfig config = loader.parse("""
                {"system": "s", "interfaces": [{"id": "r", "driver": "robot-sim", "address": "localhost"}]}""");

        InterfaceConfig robot = config.iface("r").orElseThrow();
        assertThat(robot.params()).isEqualTo(new TestDriver.Params(16));
        assertThat(robot.reconnect()).isEqualTo(Reconnect.DEFAULTS);
        assertThat(robot.address().port()).isEmpty();
    }

    @Test
    void configWithSeveralFaultsReportsEveryOneAtOnceSortedByPath() {
        String json = """
                {"system": "",
                 "limits": {"maxLineBytes": -5},
                 "status": {"port": 7004},
                 "interfaces": [{"id": "robot", "driver": "robot-sim", "address": "127.0.0.1:8101", "colour": "red"}],
                 "methods": [
                   {"id": "sonar", "type": "sonar", "layer": "sensors_actuators",
                    "inputs": {"ranges": "@robot.sonar"}, "params": {"maxRangeM": "far"}},
                   {"id": "nearest", "type": "nearest-distance", "layer": "processing", "inputs": {"ranges": "sonar.ranges"}},
                   {"id": "up", "type": "relay", "layer": "virtual", "inputs": {"in": "sonar.ranges"}},
                   {"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                    "expose": {"port": 7004}},
                   {"id": "x", "type": "teleport", "layer": "virtual"}
                 ]}""";

        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.parse(json));

        assertThat(e.errors()).extracting(ConfigError::path).containsExactly(
                "$.interfaces[0].colour",
                "$.limits.maxLineBytes",
                "$.methods[0].params.maxRangeM",
                "$.methods[2].inputs.in",
                "$.methods[3].expose.port",
                "$.methods[4].type",
                "$.system");
        assertThat(e.errors().get(3).message()).contains("layer rule");
        assertThat(e.errors().get(4).message()).contains("duplicate port 7004: already used at $.status.port");
        assertThat(e.getMessage()).startsWith("7 errors in config:");
    }

    @Test
    void missingFileIsAnErrorAtTheRoot(@TempDir Path dir) {
        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.load(dir.resolve("none.json")));

        assertThat(e.errors()).singleElement().satisfies(err -> {
            assertThat(err.path()).isEqualTo("$");
            assertThat(err.message()).contains("cannot read").contains("none.json");
        });
    }

    @Test
    void bytesThatAreNotUtf8AreAnErrorAtTheRoot(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("latin1.json");
        Files.write(file, new byte[] {'{', '"', 's', 'y', 's', 't', 'e', 'm', '"', ':', '"', (byte) 0xE9, '"', '}'});

        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.load(file));

        assertThat(e.errors()).singleElement().extracting(ConfigError::message).asString().contains("not UTF-8");
    }

    @Test
    void emptyTextAndTrailingTokensAreRejected() {
        ConfigException empty = catchThrowableOfType(ConfigException.class, () -> loader.parse("  "));
        ConfigException trailing = catchThrowableOfType(ConfigException.class,
                () -> loader.parse("{\"system\": \"a\"} {\"system\": \"b\"}"));

        assertThat(empty.errors()).singleElement().extracting(ConfigError::message).asString().contains("empty");
        assertThat(trailing.errors()).singleElement().satisfies(err -> {
            assertThat(err.path()).isEqualTo("$");
            assertThat(err.message()).contains("invalid JSON at line 1");
        });
    }

    @Test
    void oddKeysAreQuotedInPaths() {
        ConfigException e = catchThrowableOfType(ConfigException.class,
                () -> loader.parse("{\"system\": \"s\", \"my key\": 1}"));

        assertThat(e.errors()).singleElement().extracting(ConfigError::path).isEqualTo("$[\"my key\"]");
    }

    @Test
    void aDeclaredCycleLoadsAndEveryWireOnItIsACycleInput() throws Exception {
        HablaConfig config = loader.parse("""
                {"system": "t", "methods": [
                  {"id": "a", "type": "relay", "layer": "processing", "inputs": {"in": "b.out"}, "feedback": ["in"]},
                  {"id": "b", "type": "relay", "layer": "processing", "inputs": {"in": "a.out"}},
                  {"id": "c", "type": "relay", "layer": "processing", "inputs": {"in": "b.out"}}]}
                """);

        assertThat(config.method("a").orElseThrow().feedback()).containsExactly("in");
        assertThat(config.cycleInputs("a")).containsExactly("in");
        assertThat(config.cycleInputs("b")).containsExactly("in");
        assertThat(config.cycleInputs("c")).isEmpty();
    }

    @Test
    void linkChannelOfEveryInterfaceCanFeedASensorMethod() throws Exception {
        String json = """
                {"system": "s", "interfaces": [{"id": "r", "driver": "robot-sim", "address": "h:1"}],
                 "methods": [{"id": "link", "type": "relay", "layer": "processing", "inputs": {"in": "@r.link"}}]}""";

        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.parse(json));

        // the channel exists (no "has no channel" error); only the layer of the reader is wrong
        assertThat(e.errors()).singleElement().extracting(ConfigError::message).asString()
                .contains("only a sensors_actuators method reads interface channels");
    }
}
