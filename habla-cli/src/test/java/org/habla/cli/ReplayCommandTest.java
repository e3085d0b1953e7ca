package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.habla.command.ExitCodes;
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

    /** A recording of 200 outputs with the first byte of the 101st record's line broken; returns that offset. */
    private long damagedRecording(Path file) throws Exception {
        Path whole = dir.resolve("whole.habla-rec");
        org.habla.graph.ManualClock clock = new org.habla.graph.ManualClock(1_000_000);
        com.fasterxml.jackson.databind.node.ObjectNode config =
                com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.objectNode().put("system", "x");
        config.putObject("status").put("port", 0); // not 7099: a daemon running on this machine may hold it
        try (org.habla.recording.Recorder r = org.habla.recording.Recorder.create(whole,
                new org.habla.recording.RecordingHeader(1_000_000, 1.0, config, "", java.util.Map.of()), clock)) {
            for (int i = 1; i <= 200; i++) {
                clock.advanceMillis(10);
                r.output("reward", "reward", new org.habla.sample.Sample(new org.habla.sample.NumberValue(i),
                        "reward.reward", i, clock.nowMicros(), false));
            }
        }
        byte[] bytes = Files.readAllBytes(whole);
        long at = -1;
        for (int i = 0, lines = 0; i < bytes.length; i++) {
            if (bytes[i] == '\n' && ++lines == 101) {
                at = i + 1;
                break;
            }
        }
        bytes[(int) at] = '#';
        Files.write(file, bytes);
        return at;
    }

    @Test
    void aRecordingDamagedInTheMiddleIsRefusedNamingTheByteOffset() throws Exception {
        Path damaged = dir.resolve("damaged.habla-rec");
        long at = damagedRecording(damaged);

        CommandRun run = replay(damaged.toString(), "--as-fast-as-possible");

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("the recording is damaged at byte " + at + " (")
                .contains("Nothing was replayed; --salvage replays the part before byte " + at);
        assertThat(run.out()).doesNotContain("replayed");
    }

    @Test
    void salvageReplaysWhatPrecedesTheDamageAndSaysWhereItStopped() throws Exception {
        Path damaged = dir.resolve("damaged.habla-rec");
        long at = damagedRecording(damaged);

        CommandRun run = replay(damaged.toString(), "--as-fast-as-possible", "--salvage");

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.out()).contains("the recording is damaged at byte " + at + " (")
                .contains("everything before it was replayed");
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
