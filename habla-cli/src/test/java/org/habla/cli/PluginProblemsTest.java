package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.command.ExitCodes;
import org.habla.plugin.ExamplePlugin;
import org.habla.plugin.PluginJars;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plugin that is not found, cannot be loaded or registers nothing is named with its reason by {@code habla check}
 * and at a daemon's start, in the error about the type the config wanted and as a warning of its own.
 */
class PluginProblemsTest {

    /** Wires the example's {@code threshold} type behind a control socket (never bound: the tests only read it). */
    private static final String WITH_THRESHOLD = """
            {"system": "plugin-test",
             "methods": [
               {"id": "in", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                "params": {"kind": "record"}, "expose": {"port": 49401, "name": "in"}},
               {"id": "near", "type": "threshold", "layer": "processing", "inputs": {"nearest": "in.out"}}]}
            """;
    private static final String WITHOUT_THRESHOLD = """
            {"system": "plugin-test",
             "methods": [
               {"id": "in", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                "params": {"kind": "record"}, "expose": {"port": 49401, "name": "in"}}]}
            """;

    @TempDir
    Path tmp;
    private Path config;
    private Path plain;

    @BeforeEach
    void configs() throws Exception {
        config = Files.writeString(tmp.resolve("alarm.json"), WITH_THRESHOLD);
        plain = Files.writeString(tmp.resolve("plain.json"), WITHOUT_THRESHOLD);
    }

    private static PluginRegistry registry(Path named) {
        return PluginRegistry.discover(PluginJars.open(named, PluginProblemsTest.class.getClassLoader()).loader());
    }

    private CommandRun check(Path named, Path file) {
        return CommandRun.of(new CheckCommand(registry(named)), file.toString());
    }

    private String typeError(Path named) {
        CommandRun run = check(named, config);
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        return run.err().lines().filter(l -> l.startsWith("$.methods[1].type: ")).findFirst().orElseThrow(() ->
                new AssertionError("no error at $.methods[1].type: " + run.err()));
    }

    @Test
    void aPluginsFolderThatDoesNotExistIsNamedInTheUnknownTypeError() {
        Path missing = tmp.resolve("no-such-folder");
        assertThat(typeError(missing)).contains("unknown method type 'threshold' (known: channel, pass-through)",
                "plugins: --plugins " + missing + " does not exist: give a folder of plugin jars, or one jar");
    }

    @Test
    void anEmptyPluginsFolderIsNamedInTheUnknownTypeError() throws Exception {
        Path empty = Files.createDirectory(tmp.resolve("plugins"));
        assertThat(typeError(empty)).contains("plugins: --plugins " + empty + " has no .jar file");
    }

    @Test
    void aJarWithoutItsServicesFileRegistersNothingAndSaysWhichFileItLacks() throws Exception {
        Path dir = Files.createDirectory(tmp.resolve("plugins"));
        ExamplePlugin.jarWithServices(tmp, dir.resolve("alarm.jar"), null);
        assertThat(typeError(dir)).contains("plugins: alarm.jar registers nothing: it has no "
                + ExamplePlugin.SERVICES);
    }

    @Test
    void aServicesFileNamingAClassTheJarLacksSaysWhichClassAndWhichJar() throws Exception {
        Path dir = Files.createDirectory(tmp.resolve("plugins"));
        ExamplePlugin.jarWithServices(tmp, dir.resolve("alarm.jar"), "org.example.habla.ThresholdProvder\n");
        assertThat(typeError(dir)).contains("plugins: alarm.jar: the provider org.example.habla.ThresholdProvder its "
                + ExamplePlugin.SERVICES + " lists cannot be loaded: Provider org.example.habla.ThresholdProvder not found")
                .doesNotContain("registers nothing");
    }

    @Test
    void pluginsNamingTheJarItselfLoadsItAndCheckSaysWhatItRegistered() throws Exception {
        Path jar = ExamplePlugin.jar(tmp, tmp.resolve("threshold-method.jar"));
        CommandRun run = check(jar, config);
        assertThat(run.exitCode()).as(run.err()).isEqualTo(ExitCodes.OK);
        assertThat(run.out()).contains("plugin threshold-method.jar: method type threshold");
        assertThat(run.err()).isEmpty();
    }

    @Test
    void aValidConfigBesideAPluginThatRegistersNothingIsValidWithAWarning() throws Exception {
        Path dir = Files.createDirectory(tmp.resolve("plugins"));
        ExamplePlugin.jarWithServices(tmp, dir.resolve("alarm.jar"), null);
        CommandRun run = check(dir, plain);
        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.err()).startsWith("warning: plugin problem: alarm.jar registers nothing");
    }

    @Test
    void aDaemonsStartLogsThePluginProblemAndRefusesTheConfigNamingIt() throws Exception {
        Path dir = Files.createDirectory(tmp.resolve("plugins"));
        ExamplePlugin.jarWithServices(tmp, dir.resolve("alarm.jar"), null);
        try (LogLines log = new LogLines(RunCommand.class)) {
            CommandRun run = CommandRun.of(new RunCommand(registry(dir)), config.toString());
            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(run.err()).contains("the daemon does not start", "unknown method type 'threshold'",
                    "alarm.jar registers nothing");
            assertThat(log.at(Level.WARN)).singleElement().asString()
                    .startsWith("plugin problem: alarm.jar registers nothing: it has no " + ExamplePlugin.SERVICES);
        }
    }
}
