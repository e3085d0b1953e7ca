package org.habla.recording;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.habla.driver.ChannelDescriptor;
import org.habla.graph.ManualClock;
import org.habla.net.FrameWriter;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The recording file: what is written reads back the same, and a file cut anywhere reads back every whole record. */
@Timeout(60)
class RecordingFileTest {

    @TempDir
    Path dir;

    /** A small rover's header: a sonar reading with its poses, a motion command (the MCAP test records it too). */
    static RecordingHeader header() {
        ObjectNode config = JsonNodeFactory.instance.objectNode().put("system", "test-rover");
        ObjectNode poses = JsonNodeFactory.instance.objectNode();
        poses.putArray("poses").add(0.1).add(0.2);
        return new RecordingHeader(1_000_000, 2.0, config, "/configs",
                Map.of("robot", List.of(ChannelDescriptor.reading("sonar", PayloadKind.VECTOR, "m").withMetadata(poses),
                        ChannelDescriptor.command("motion", PayloadKind.VECTOR, "m/s", true))));
    }

    /** One of every kind of record and payload, written through the tap as the engine would. */
    private static Path record(Path file, int rounds) throws IOException {
        ManualClock clock = new ManualClock(1_000_000);
        byte[] pcm = new byte[1_600];
        byte[] jpeg = new byte[3_000];
        Random random = new Random(3);
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
            }
            r.link("robot", false, clock.nowMicros());
        }
        return file;
    }

    @Test
    void everyRecordReadsBackAsItWasWrittenAndACleanCloseEndsTheFile() throws Exception {
        Path file = record(dir.resolve("run.habla-rec"), 20);
        Recording rec = RecordingReader.readAll(file);

        assertThat(rec.cut()).isEmpty();
        assertThat(rec.complete()).isTrue();
        assertThat(rec.header().config().path("system").asText()).isEqualTo("test-rover");
        assertThat(rec.header().timeScale()).isEqualTo(2.0);
        assertThat(rec.header().interfaces().get("robot")).isEqualTo(header().interfaces().get("robot"));
        assertThat(rec.events(RecordedEvent.LinkChange.class)).extracting(RecordedEvent.LinkChange::up).containsExactly(true, false);
        List<RecordedEvent.Reading> readings = rec.events(RecordedEvent.Reading.class);
        assertThat(readings).hasSize(60);
        assertThat(readings.get(0).sample().payload()).isEqualTo(VectorValue.of(1, 0.5, Double.NaN));
        assertThat(readings.get(0).t()).isEqualTo(1_050_000);
        assertThat(readings.get(1).sample().payload()).isInstanceOf(AudioChunk.class);
        assertThat(((AudioChunk) readings.get(1).sample().payload()).byteCount()).isEqualTo(1_600);
        RecordedEvent.Reading image = readings.get(5);
        assertThat(image.iface()).isEqualTo("cam");
        assertThat(image.sample().stale()).isTrue();
        assertThat(image.sample().payload()).isEqualTo(ImageFrame.of(208, 160, "jpeg",
                ((ImageFrame) image.sample().payload()).data()));
        List<RecordedEvent.Command> commands = rec.events(RecordedEvent.Command.class);
        assertThat(commands).extracting(RecordedEvent.Command::sent).startsWith(true, true, false);
        assertThat(commands.get(0).sample()).isEqualTo(new Sample(VectorValue.of(0.2, -0.6), "wheels.motion", 1, 1_050_000 - 7, false));
        assertThat(rec.events(RecordedEvent.ControlWrite.class)).extracting(w -> w.sample().payload())
                .startsWith(new TextValue("forward"), new TextValue("left"));
        List<RecordedEvent.Output> outputs = rec.events(RecordedEvent.Output.class);
        assertThat(outputs).hasSize(40);
        assertThat(outputs.get(2).sample()).isEqualTo(new Sample(RecordValue.builder().put("distanceM", 0.5)
                .put("angleRad", -0.25).put("seen", true).build(), "distance.distance_angle", 2, 1_100_000 - 3, false));
        RecordedEvent.End end = (RecordedEvent.End) rec.events().get(rec.events().size() - 1);
        assertThat(end.written()).isEqualTo(20 * 7 + 2);
        assertThat(end.dropped()).isZero();
    }

    @Test
    void aFileCutAtAnyByteReadsBackEveryWholeRecordAndReportsTheCut() throws Exception {
        Path whole = record(dir.resolve("whole.habla-rec"), 12);
        Recording full = RecordingReader.readAll(whole);
        byte[] bytes = Files.readAllBytes(whole);
        // Where each record ends, from encoding the records one by one: independent of the reader's counting.
        List<Long> ends = new ArrayList<>();
        long at = encode(RecordingCodec.header(full.header())).length;
        long headerEnd = at;
        for (RecordedEvent e : full.events()) {
            at += encode(RecordingCodec.frame(e)).length;
            ends.add(at);
        }
        assertThat(at).as("the records fill the file exactly").isEqualTo(bytes.length);

        Random random = new Random(42);
        List<Long> cuts = new ArrayList<>(ends);
        for (int i = 0; i < 300; i++) {
            cuts.add(headerEnd + (long) (random.nextDouble() * (bytes.length - headerEnd)));
        }
        for (long cutAt : cuts) {
            Path cutFile = dir.resolve("cut.habla-rec");
            Files.write(cutFile, Arrays.copyOf(bytes, (int) cutAt));
            Recording rec = RecordingReader.readAll(cutFile);
            int wholeRecords = (int) ends.stream().filter(end -> end <= cutAt).count();
            assertThat(rec.events()).as("records read from a file cut at %d", cutAt)
                    .isEqualTo(full.events().subList(0, wholeRecords));
            long lastWholeEnd = wholeRecords == 0 ? headerEnd : ends.get(wholeRecords - 1);
            if (lastWholeEnd == cutAt) {
                assertThat(rec.cut()).as("a file cut between records has no torn record").isEmpty();
            } else {
                assertThat(rec.cut()).as("the cut at %d", cutAt).isPresent();
                assertThat(rec.cut().get().offset()).isEqualTo(lastWholeEnd);
                assertThat(rec.cut().get().ignoredBytes()).isEqualTo(cutAt - lastWholeEnd);
                assertThat(rec.cut().get().reason()).isNotBlank();
                assertThat(rec.cut().get().torn()).as("a file cut at %d ends in a torn record", cutAt).isTrue();
            }
        }
    }

    /** Where each record after the header starts, and the file's length last. */
    private static List<Long> recordStarts(Recording full) throws IOException {
        List<Long> starts = new ArrayList<>();
        long at = encode(RecordingCodec.header(full.header())).length;
        for (RecordedEvent e : full.events()) {
            starts.add(at);
            at += encode(RecordingCodec.frame(e)).length;
        }
        starts.add(at);
        return starts;
    }

    @Test
    void aLineBrokenInTheMiddleIsDamageNamedByItsOffsetNotATornEnd() throws Exception {
        Path whole = record(dir.resolve("whole.habla-rec"), 40);
        Recording full = RecordingReader.readAll(whole);
        List<Long> starts = recordStarts(full);
        int broken = starts.size() / 2;
        byte[] bytes = Files.readAllBytes(whole);
        bytes[(int) (long) starts.get(broken) + 2] = '#';
        Path damaged = Files.write(dir.resolve("damaged.habla-rec"), bytes);

        Recording rec = RecordingReader.readAll(damaged);

        assertThat(rec.events()).isEqualTo(full.events().subList(0, broken));
        Cut cut = rec.cut().orElseThrow();
        assertThat(cut.damage()).isTrue();
        assertThat(cut.offset()).isEqualTo(starts.get(broken));
        assertThat(cut.ignoredBytes()).isEqualTo(bytes.length - starts.get(broken));
        assertThat(cut.nextWholeRecord()).hasValue(starts.get(broken + 1));
        assertThat(cut.describe()).startsWith("the recording is damaged at byte " + starts.get(broken) + " (");
    }

    @Test
    void aBlockSizeThatSwallowsTheRestOfTheFileIsDamageWhenWholeRecordsLieInside() throws Exception {
        Path whole = record(dir.resolve("whole.habla-rec"), 40);
        Recording full = RecordingReader.readAll(whole);
        List<Long> starts = recordStarts(full);
        int audio = -1;
        for (int i = full.events().size() / 3; audio < 0; i++) {
            if (full.events().get(i) instanceof RecordedEvent.Reading r && r.channel().equals("audio")) {
                audio = i;
            }
        }
        byte[] bytes = Files.readAllBytes(whole);
        String line = new String(bytes, (int) (long) starts.get(audio), 400, java.nio.charset.StandardCharsets.ISO_8859_1);
        int digits = starts.get(audio).intValue() + line.indexOf("\"bytes\":1600") + "\"bytes\":".length();
        // 1600 becomes 9600: the block now runs over the records after it, and the file ends inside it.
        bytes[digits] = '9';
        byte[] shortened = Arrays.copyOf(bytes, (int) (starts.get(audio) + 5_000));
        Path damaged = Files.write(dir.resolve("swallowed.habla-rec"), shortened);

        Cut cut = RecordingReader.readAll(damaged).cut().orElseThrow();

        assertThat(cut.offset()).isEqualTo(starts.get(audio));
        assertThat(cut.damage()).as("whole records follow inside the over-long block: %s", cut).isTrue();
        assertThat(cut.nextWholeRecord()).hasValue(starts.get(audio + 1));
    }

    @Test
    void aFileThatIsNotARecordingIsRefusedWithAReason() throws Exception {
        Path notOne = dir.resolve("config.json");
        Files.writeString(notOne, "{\"system\":\"x\"}\n");
        assertThatThrownBy(() -> RecordingReader.readAll(notOne)).isInstanceOf(RecordingException.class)
                .hasMessageContaining("not a HABLA recording");
        Path empty = Files.createFile(dir.resolve("empty"));
        assertThatThrownBy(() -> RecordingReader.readAll(empty)).hasMessageContaining("empty");
        Path whole = record(dir.resolve("r.habla-rec"), 1);
        Path torn = dir.resolve("torn");
        Files.write(torn, Arrays.copyOf(Files.readAllBytes(whole), 40));
        assertThatThrownBy(() -> RecordingReader.readAll(torn)).hasMessageContaining("header record is not whole");
    }

    @Test
    void aRecordingIsNeverOverwritten() throws Exception {
        Path file = record(dir.resolve("keep.habla-rec"), 1);
        long size = Files.size(file);
        assertThatThrownBy(() -> Recorder.create(file, header(), new ManualClock(0)))
                .isInstanceOf(java.nio.file.FileAlreadyExistsException.class);
        assertThat(Files.size(file)).isEqualTo(size);
    }

    @Test
    void everyEventOfferedFasterThanTheDiskTakesItIsWrittenOrCountedAsDroppedNeverWaitedFor() throws Exception {
        Path file = dir.resolve("flood.habla-rec");
        int offered = 200_000;
        ManualClock clock = new ManualClock(1_000_000);
        Sample s = new Sample(new NumberValue(0.5), "@robot.value", 1, 1_000_000, false);
        try (Recorder r = Recorder.create(file, header(), clock)) {
            for (int i = 0; i < offered; i++) {
                r.reading("robot", "value", s);
            }
        }
        Recording rec = RecordingReader.readAll(file);
        RecordedEvent.End end = (RecordedEvent.End) rec.events().get(rec.events().size() - 1);
        assertThat(end.written() + end.dropped()).as("written %s, dropped %s", end.written(), end.dropped())
                .isEqualTo(offered);
        assertThat(rec.events(RecordedEvent.Reading.class)).hasSize((int) end.written());
        List<RecordedEvent.Dropped> drops = rec.events(RecordedEvent.Dropped.class);
        if (end.dropped() > 0 && !drops.isEmpty()) {
            assertThat(drops.get(drops.size() - 1).total()).isLessThanOrEqualTo(end.dropped());
        }
    }

    private static byte[] encode(org.habla.net.Frame f) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(b);
        w.write(f);
        w.flush();
        return b.toByteArray();
    }
}
