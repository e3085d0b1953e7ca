package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.habla.recording.RecordedEvent;
import org.habla.recording.Recording;
import org.habla.recording.RecordingSource;
import org.habla.replay.OutputComparison;
import org.habla.sample.NumberValue;
import org.habla.sample.TextValue;
import org.habla.sim.scenario.TruthLink;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A Pioneer episode recorded as a user records one — the simulated Pioneer, the daemon with config/pioneer.json
 * and {@code --record} in its own JVM, a Python client writing actions, the teacher's notes and rewards — then
 * replayed with {@code habla replay} in another JVM: the virtual layer's exposed outputs come out the same,
 * value for value and in order. And a daemon killed with SIGKILL mid-recording leaves a file that replays.
 */
@Timeout(300)
class PioneerRecordReplayTest {

    private static final List<String> VIRTUAL = List.of("distance.distance_angle", "command.command", "reward.reward");

    static SimulatedDeployment rig;
    static Path dir;

    @BeforeAll
    static void start() throws Exception {
        dir = Files.createDirectories(Path.of("target/e2e/pioneer-replay"));
        rig = new SimulatedDeployment("pioneer", "pioneer-room", 1, dir, c -> { });
        rig.startSimulator();
    }

    @AfterAll
    static void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    /** Teacher's notes and rewards, and the client's actions, for about {@code seconds} of simulated time. */
    private static void episode() throws Exception {
        rig.place(1.0, 1.0, 0.3);
        rig.after(1.0);
        String[][] lessons = {{"forward", "1"}, {"left", "-1"}};
        for (String[] lesson : lessons) {
            rig.truth.send(TruthLink.op("say").put("label", lesson[0]));
            rig.after(0.8);
            rig.probe(20_000, "act", "" + rig.port("action"), lesson[0], "0.3");
            rig.after(0.7);
            rig.truth.send(TruthLink.op("reward").put("value", Integer.parseInt(lesson[1])));
            rig.after(0.8);
        }
    }

    private static List<String> values(Recording r, String stream) {
        return r.events(RecordedEvent.Output.class).stream()
                .filter(o -> (o.method() + "." + o.output()).equals(stream))
                .map(o -> OutputComparison.canonical(o.sample().payload())).toList();
    }

    private static DaemonProcess replay(Path file, Path out) throws Exception {
        DaemonProcess p = DaemonProcess.start(dir.resolve("replay-" + System.nanoTime() + ".log"), "replay",
                file.toString(), "--as-fast-as-possible", "--record", out.toString());
        assertThat(p.waitFor(120_000)).as("habla replay exits 0; output:%n%s", p.output()).isZero();
        return p;
    }

    @Test
    void aRecordedPioneerEpisodeReplaysToTheSameVirtualOutputsValueForValue() throws Exception {
        Path file = dir.resolve("episode-" + System.nanoTime() + ".mcap");
        // The recording starts where the episode does, not at the room's default start pose.
        rig.place(1.0, 1.0, 0.3);
        rig.startDaemon("--record", file.toString());
        rig.awaitReady(60_000);
        episode();
        assertThat(rig.daemon.terminate(10_000)).as("the daemon stops on SIGTERM").isZero();

        Recording recorded = RecordingSource.readAll(file);
        assertThat(recorded.complete()).as("a daemon stopped cleanly ends its recording").isTrue();
        assertThat(recorded.events(RecordedEvent.Reading.class)).as("readings recorded").hasSizeGreaterThan(100);
        assertThat(recorded.events(RecordedEvent.ControlWrite.class)).extracting(w -> w.sample().payload())
                .containsExactly(new TextValue("forward"), new TextValue("left"));
        assertThat(values(recorded, "command.command")).containsExactly(
                OutputComparison.canonical(new TextValue("forward")), OutputComparison.canonical(new TextValue("left")));
        assertThat(values(recorded, "reward.reward")).containsSubsequence(
                OutputComparison.canonical(new NumberValue(1)), OutputComparison.canonical(new NumberValue(-1)));
        assertThat(values(recorded, "distance.distance_angle")).hasSizeGreaterThan(30);
        McapCheck.independentReadersAgree(file, recorded);

        Path again = dir.resolve("replayed-" + System.nanoTime() + ".mcap");
        DaemonProcess replay = replay(file, again);
        Recording replayed = RecordingSource.readAll(again);
        for (String stream : VIRTUAL) {
            assertThat(values(replayed, stream)).as("%s replayed; replay said:%n%s", stream, replay.output())
                    .isEqualTo(values(recorded, stream));
        }
        assertThat(replay.output()).contains("distance.distance_angle: all ", "command.command: all ",
                "reward.reward: all ");
    }

    @Test
    void aDaemonKilledMidRecordingLeavesAFileThatReplays() throws Exception {
        Path file = dir.resolve("killed-" + System.nanoTime() + ".mcap");
        rig.startDaemon("--record", file.toString());
        rig.awaitReady(60_000);
        rig.place(1.2, 0.8, 0.0);
        rig.truth.send(TruthLink.op("say").put("label", "right"));
        rig.probe(20_000, "act", "" + rig.port("action"), "right", "0.3");
        rig.after(1.5);
        rig.daemon.close();   // SIGKILL: no shutdown hook, no end record

        Recording recorded = RecordingSource.readAll(file);
        assertThat(recorded.complete()).as("a killed daemon writes no end record").isFalse();
        assertThat(values(recorded, "distance.distance_angle")).hasSizeGreaterThan(10);
        assertThat(recorded.events(RecordedEvent.ControlWrite.class)).hasSize(1);

        Path again = dir.resolve("replayed-killed-" + System.nanoTime() + ".mcap");
        DaemonProcess replay = replay(file, again);
        assertThat(replay.output()).contains("replayed ").contains("did not stop cleanly");
        Recording replayed = RecordingSource.readAll(again);
        for (String stream : VIRTUAL) {
            List<String> before = values(recorded, stream);
            List<String> after = values(replayed, stream);
            // What the recorder had not flushed when it was killed may add a value or two at the end.
            assertThat(after.subList(0, Math.min(after.size(), before.size()))).as("%s replayed", stream)
                    .isEqualTo(before.subList(0, Math.min(after.size(), before.size())));
            assertThat(after.size()).as("%s: replayed %s, recorded %s", stream, after.size(), before.size())
                    .isBetween(before.size(), before.size() + 2);
        }
    }
}
