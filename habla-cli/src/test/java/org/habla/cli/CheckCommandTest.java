package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigError;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.TestPlugins;
import org.habla.testing.TestConfigs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class CheckCommandTest {

    @TempDir
    Path dir;

    @Test
    void validConfigIsSummarisedAndExitsZero() {
        Path config = TestConfigs.file("valid/pioneer-like.json");

        CommandRun run = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.err()).isEmpty();
        assertThat(run.outFlat())
                .startsWith(config + " is valid: system 'test-robot'")
                .contains("1 interface (robot: robot-sim at 127.0.0.1:8101)")
                .contains("6 methods (2 sensors_actuators, 2 processing, 2 virtual)")
                .contains("2 control sockets (distance_angle on 127.0.0.1:7002, action on 127.0.0.1:7004)")
                .contains("1 method on a worker (action on 127.0.0.1:7600)")
                .contains("status on 127.0.0.1:7199")
                .contains("motion watchdog 500 ms");
        assertThat(run.out().lines()).allSatisfy(l -> assertThat(l.length()).isLessThanOrEqualTo(100));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("brokenConfigs")
    void everyBrokenConfigPrintsItsErrorAtItsPathAndExitsTwo(String name) {
        Path config = TestConfigs.file("broken/" + name);
        List<ConfigError> expected = errorsOf(config);

        CommandRun run = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.out()).isEmpty();
        List<String> lines = run.err().lines().toList();
        assertThat(lines.get(0)).isEqualTo(config + ": 1 error:");
        assertThat(lines.subList(1, lines.size()))
                .containsExactly(expected.get(0).path() + ": " + expected.get(0).message());
    }

    @Test
    void everyErrorOfAConfigIsPrintedSortedByPath() throws IOException {
        Path config = dir.resolve("many.json");
        Files.writeString(config, """
                {"system": 5, "limits": {"maxLineBytes": 0}, "colour": "red",
                 "interfaces": [{"id": "robot", "driver": "arcos", "address": "127.0.0.1"}],
                 "methods": [{"id": "s", "type": "sonar", "layer": "sensors", "inputs": {"ranges": "@robot.sonar"}}]}
                """);

        CommandRun run = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        List<String> lines = run.err().lines().toList();
        assertThat(lines.get(0)).isEqualTo(config + ": 5 errors:");
        assertThat(lines.subList(1, lines.size())).extracting(l -> l.substring(0, l.indexOf(": ")))
                .containsExactly("$.colour", "$.interfaces[0].driver", "$.limits.maxLineBytes", "$.methods[0].layer",
                        "$.system");
    }

    @Test
    void aSecuredConfigIsSummarisedWithHowEachSocketIsGuarded(@org.junit.jupiter.api.io.TempDir Path dir)
            throws IOException {
        Files.writeString(Files.createFile(dir.resolve("lab.credentials.json"),
                java.nio.file.attribute.PosixFilePermissions.asFileAttribute(
                        java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"))),
                "{\"clients\": [{\"name\": \"mdb\", \"token\": \"a-token-of-twenty-chars\", "
                        + "\"roles\": {\"*\": \"command\"}}]}");
        Path config = Files.writeString(dir.resolve("lab.json"), """
                {"system": "t", "security": {"credentials": "lab.credentials.json"},
                 "interfaces": [{"id": "robot", "driver": "robot-sim", "address": "127.0.0.1:8101"}],
                 "methods": [{"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                              "expose": {"port": 7004, "bind": "0.0.0.0"}}]}
                """);
        CommandRun run = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());
        assertThat(run.exitCode()).as(run.err()).isEqualTo(ExitCodes.OK);
        assertThat(run.out().replace('\n', ' ')).contains("action on 0.0.0.0:7004 (authenticated)",
                "1 client in lab.credentials.json", "audit log habla-audit.log");
    }

    @Test
    void aMissingFileIsAnErrorAtTheRoot() {
        Path config = dir.resolve("nowhere.json");

        CommandRun run = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("\n$: cannot read " + config + ": no such file");
    }

    @Test
    void runRefusesABrokenConfigWithTheSameLinesAsCheck() {
        Path config = TestConfigs.file("broken/unknown-channel-reference.json");

        CommandRun check = CommandRun.of(new CheckCommand(TestPlugins.registry()), config.toString());
        CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), config.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err().lines().findFirst()).hasValue(config + ": 1 error; the daemon does not start:");
        assertThat(run.err().lines().skip(1)).containsExactlyElementsOf(check.err().lines().skip(1).toList());
    }

    @Test
    void checkIsASubcommandOfHabla() {
        assertThat(Habla.commandLine().getSubcommands()).containsKey("check");
    }

    static Stream<String> brokenConfigs() throws IOException {
        try (Stream<Path> files = Files.list(TestConfigs.file("broken"))) {
            return files.map(p -> p.getFileName().toString()).sorted().toList().stream();
        }
    }

    private static List<ConfigError> errorsOf(Path config) {
        ConfigException e = catchThrowableOfType(ConfigException.class,
                () -> new ConfigLoader(TestPlugins.registry()).load(config));
        assertThat(e).as("%s is broken", config).isNotNull();
        return e.errors();
    }

}
