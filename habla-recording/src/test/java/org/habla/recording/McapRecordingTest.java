package org.habla.recording;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.habla.graph.ManualClock;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Recordings in MCAP: the same events as the line format, a file cut anywhere, damage in the middle. */
@Timeout(120)
class McapRecordingTest {

    @TempDir
    Path dir;

    private static RecordingHeader header() {
        return RecordingFileTest.header();
    }

    /** Every kind of event and payload, through the recorder's tap as the engine would; a pause every few rounds. */
    private static Path record(Path file, int rounds) throws Exception {
        ManualClock clock = new ManualClock(1_000_000);
        Random random = new Random(3);
        byte[] pcm = new byte[1_600];
        byte[] jpeg = new byte[3_000];
        try (Recorder r = Recorder.create(file, header(), clock)) {
            r.link("robot", true, clock.nowMicros());
            for (int i = 1; i <= rounds; i++) {
                clock.advanceMillis(50);
                random.nextBytes(pcm);
                random.nextBytes(jpeg);
                r.reading("robot", "sonar", new Sample(VectorValue.of(i, 0.5, Double.NaN), "@robot.sonar", i, clock.nowMicros(), false));
                r.reading("mic", "audio", new Sample(AudioChunk.of(AudioFormat.MONO_16K, pcm), "@mic.audio", i, clock.nowMicros(), false));
                r.reading("cam", "camera", new Sample(ImageFrame.of(208, 160, "jpeg", jpeg), "@cam.camera", i, clock.nowMicros(), i % 2 == 0));
                r.control("action", "action", new Sample(new TextValue(i % 2 == 0 ? "left" : "forward"), "control:action", i, clock.nowMicros(), false));
                r.command("robot", "motion", new Sample(VectorValue.of(0.2, -0.6), "wheels.motion", i, clock.nowMicros() - 7, false), i % 3 != 0);
                r.output("distance", "distance_angle", new Sample(RecordValue.builder().put("distanceM", 1.0 / i)
                        .put("angleRad", -0.25).put("seen", true).build(), "distance.distance_angle", i, clock.nowMicros() - 3, false));
                r.output("reward", "reward", new Sample(new NumberValue(-1), "reward.reward", i, clock.nowMicros(), false));
                r.periodic("tick:distance", clock.nowMicros(), i);
                if (i % 5 == 0) {
                    r.writerLeft("action");
                    assertThat(r.flush(30_000)).as("the writer closed a chunk").isTrue();
                }
            }
            r.link("robot", false, clock.nowMicros());
        }
        return file;
    }

    private static Recording readAll(Path file) throws Exception {
        try (RecordingSource s = RecordingSource.open(file)) {
            List<RecordedEvent> events = new ArrayList<>();
            for (RecordedEvent e = s.next(); e != null; e = s.next()) {
                events.add(e);
            }
            return new Recording(s.header(), events, s.cut());
        }
    }

    @Test
    void anMcapRecordingReadsBackTheSameEventsAsTheLineFormat() throws Exception {
        Recording mcap = readAll(record(dir.resolve("run.mcap"), 20));
        Recording lines = readAll(record(dir.resolve("run.habla-rec"), 20));
        assertThat(McapRecordingReader.isMcap(dir.resolve("run.mcap"))).isTrue();
        assertThat(mcap.cut()).isEmpty();
        assertThat(mcap.complete()).isTrue();
        assertThat(mcap.header()).isEqualTo(lines.header());
        List<RecordedEvent> a = withoutEndTimes(mcap.events());
        List<RecordedEvent> b = withoutEndTimes(lines.events());
        assertThat(a).hasSize(b.size()).isEqualTo(b);
        assertThat(mcap.events(RecordedEvent.Reading.class).get(2).sample().payload())
                .isInstanceOf(ImageFrame.class);
    }

    @Test
    void anMcapFileCutAnywhereReadsBackEveryWholeChunkAndReportsTheCut() throws Exception {
        Path whole = record(dir.resolve("whole.mcap"), 30);
        Recording full = readAll(whole);
        byte[] bytes = Files.readAllBytes(whole);
        long dataEnd = dataEndOffset(bytes);
        Random random = new Random(42);
        for (int i = 0; i < 200; i++) {
            long cutAt = 200 + (long) (random.nextDouble() * (dataEnd - 200));
            Path cutFile = dir.resolve("cut.mcap");
            Files.write(cutFile, Arrays.copyOf(bytes, (int) cutAt));
            Recording rec = readAll(cutFile);
            assertThat(rec.events()).as("events of a file cut at %d", cutAt)
                    .isEqualTo(full.events().subList(0, rec.events().size()));
            assertThat(rec.complete()).isFalse();
            if (rec.cut().isPresent()) {
                assertThat(rec.cut().get().offset() + rec.cut().get().ignoredBytes()).isEqualTo(cutAt);
                assertThat(rec.cut().get().reason()).isNotBlank();
                assertThat(rec.cut().get().torn()).as("a file cut at %d ends in a torn record", cutAt).isTrue();
            }
        }
        // A kill in the middle of a run loses only the chunk being written: cut inside the third chunk, the
        // events of the first two are all there.
        List<long[]> chunks = chunks(bytes);
        long[] third = chunks.get(2);
        Path inThird = dir.resolve("third.mcap");
        Files.write(inThird, Arrays.copyOf(bytes, (int) (third[0] + third[1] / 2)));
        Recording rec = readAll(inThird);
        Path twoChunks = dir.resolve("two.mcap");
        Files.write(twoChunks, Arrays.copyOf(bytes, (int) third[0]));
        assertThat(rec.events()).isNotEmpty().isEqualTo(readAll(twoChunks).events());
        assertThat(rec.cut().get().offset()).isEqualTo(third[0]);
    }

    @Test
    void aDamagedChunkInTheMiddleIsReportedWithItsOffsetAndWhatCameBeforeItIsRead() throws Exception {
        Path whole = record(dir.resolve("whole.mcap"), 30);
        Recording full = readAll(whole);
        byte[] bytes = Files.readAllBytes(whole);
        List<long[]> chunks = chunks(bytes);
        assertThat(chunks.size()).as("chunks in the file").isGreaterThanOrEqualTo(3);
        long[] victim = chunks.get(chunks.size() / 2);
        long[] after = chunks.get(chunks.size() / 2 + 1);
        byte[] damaged = bytes.clone();
        damaged[(int) (victim[0] + victim[1] - 5)] ^= 0x5a;
        Path file = dir.resolve("damaged.mcap");
        Files.write(file, damaged);
        Recording rec = readAll(file);
        Optional<Cut> cut = rec.cut();
        assertThat(cut).isPresent();
        assertThat(cut.get().offset()).isEqualTo(victim[0]);
        assertThat(cut.get().reason()).startsWith("damaged:").contains("byte " + victim[0]);
        assertThat(cut.get().damage()).as("a chunk failing its CRC with whole chunks after it is not a torn end").isTrue();
        assertThat(cut.get().nextWholeRecord()).hasValue(after[0]);
        assertThat(rec.events()).isNotEmpty().isEqualTo(full.events().subList(0, rec.events().size()));
        assertThat(rec.events().size()).isLessThan(full.events().size());
    }

    @Test
    void aFileThatIsNotAnHablaMcapIsRefusedWithAReason() throws Exception {
        Path bare = dir.resolve("bare.mcap");
        Files.write(bare, McapWriter.MAGIC);
        assertThatThrownBy(() -> readAll(bare)).isInstanceOf(RecordingException.class)
                .hasMessageContaining("not a HABLA recording");
    }

    /** The End record's own time is the writer's clock at close: the same in both files, but compared anyway. */
    private static List<RecordedEvent> withoutEndTimes(List<RecordedEvent> events) {
        return events.stream().map(e -> e instanceof RecordedEvent.End x ? new RecordedEvent.End(0, x.written(),
                x.dropped()) : e).toList();
    }

    /** Each chunk record's offset and length, walking the data section's records. */
    private static List<long[]> chunks(byte[] file) {
        List<long[]> out = new ArrayList<>();
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        b.position(McapWriter.MAGIC.length);
        while (b.remaining() > 9) {
            int at = b.position();
            int op = b.get() & 0xff;
            long len = b.getLong();
            if (op == McapWriter.OP_DATA_END) {
                break;
            }
            if (op == McapWriter.OP_CHUNK) {
                out.add(new long[] {at, 9 + len});
            }
            b.position((int) (b.position() + len));
        }
        return out;
    }

    private static long dataEndOffset(byte[] file) {
        List<long[]> c = chunks(file);
        long[] last = c.get(c.size() - 1);
        return last[0] + last[1];
    }

}
