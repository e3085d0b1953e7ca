package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code habla replay} refuses what it cannot replay with a reason and the usage exit code. */
class ReplayCommandTest {

    @TempDir
    Path dir;

    private CommandRun replay(String... args) {
        return CommandRun.of(new ReplayCommand(PluginRegistry.of(java.util.List.of(), java.util.List.of())), args);
    }

    @Test
    void aFileThatIsNotARecordingIsRefused() throws Exception {
        Path config = Files.writeString(dir.resolve("pioneer.json"), "{\"system\": \"x\"}\n");
        CommandRun run = replay(config.toString(), "--as-fast-as-possible");
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("habla replay:").contains("not a HABLA recording");
    }

    @Test
    void aMissingFileIsRefused() {
        CommandRun run = replay(dir.resolve("nothing.habla-rec").toString());
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("cannot read");
    }

    @Test
    void aRecordingWhoseHeaderWasCutIsRefusedAndSaysSo() throws Exception {
        byte[] header = "{\"type\":\"recording\",\"format\":\"habla-recording\",\"version\":1,\"config\":{}}\n"
                .getBytes(java.nio.charset.StandardCharsets.UTF_8);
        Path cut = Files.write(dir.resolve("cut.habla-rec"), Arrays.copyOf(header, 30));
        CommandRun run = replay(cut.toString());
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("not whole");
    }

    @Test
    void speedAndAsFastAsPossibleExcludeEachOther() {
        CommandRun run = replay("x.habla-rec", "--speed", "2", "--as-fast-as-possible");
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("mutually exclusive");
    }

    @Test
    void aSpeedOfZeroIsRefused() {
        CommandRun run = replay("x.habla-rec", "--speed", "0");
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("--speed must be above 0");
    }
}
