package org.habla.methods.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.habla.methods.gaze.HeadPose;
import org.habla.methods.emotion.TeacherEmotion;
import org.habla.methods.motion.MotionLimits;
import org.habla.methods.perception.NearestObstacle;
import org.habla.methods.position.TargetPosition;
import org.habla.methods.room.Climate;
import org.habla.methods.room.ComfortReport;
import org.habla.methods.room.CoverCommand;
import org.habla.methods.room.LampCommand;
import org.habla.methods.room.LampLevels;
import org.habla.methods.room.SpeakerCommand;
import org.habla.methods.sensors.ButtonStates;
import org.habla.methods.virtual.LinkStatus;
import org.habla.methods.virtual.TargetBearing;
import org.habla.methods.vision.BlobList;
import org.habla.sample.RecordField;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

/**
 * The method library's typed records: each one's JSON has the fields its {@link RecordForm#layout()} declares
 * (every required one, no other), byte for byte as the record was written before it was typed, and a record read
 * back from that JSON, as a method reads one that came from a socket, a recording or a worker, equals the typed one
 * it was written from.
 */
class RecordFormsTest {

    private record Case<T extends RecordForm>(Class<T> type, List<T> examples, Function<RecordValue, T> read) {
    }

    private static final RangeScan SCAN = new RangeScan(new double[] {0.8, 5.0}, new boolean[] {true, false},
            new double[] {5.0, 5.0}, List.of(new PlanarPose(0.069, 0.136, 1.5708), new PlanarPose(0.1, -0.1, -0.5)));
    private static final RangeScan SCAN_WITHOUT_POSES = new RangeScan(new double[] {1.25}, new boolean[] {true},
            new double[] {3.0}, List.of());

    /** The JSON of each case's first example as the record was written before it was typed. */
    private static final Map<Class<?>, String> GOLDEN = Map.ofEntries(
            Map.entry(RangeScan.class, "{\"rangesM\":[0.8,5.0],\"valid\":[true,false],\"maxRangesM\":[5.0,5.0],"
                    + "\"poses\":[{\"xM\":0.069,\"yM\":0.136,\"thetaRad\":1.5708},{\"xM\":0.1,\"yM\":-0.1,"
                    + "\"thetaRad\":-0.5}]}"),
            Map.entry(PlanarPose.class, "{\"xM\":1.0,\"yM\":-2.0,\"thetaRad\":0.5}"),
            Map.entry(CameraModel.class, "{\"hfovRad\":1.0,\"vfovRad\":0.75,\"width\":208,\"height\":160,"
                    + "\"heightM\":0.3}"),
            Map.entry(HeadPose.class, "{\"tiltRad\":-0.2,\"panRad\":0.4,\"nodRad\":0.1}"),
            Map.entry(MotionLimits.class, "{\"maxVelMps\":0.5,\"maxRotVelRadps\":1.2}"),
            Map.entry(NearestObstacle.class, "{\"distanceM\":0.42,\"angleRad\":0.52,\"xM\":0.41,\"yM\":0.27,"
                    + "\"sensor\":2,\"input\":\"scan\",\"valid\":true,\"aheadM\":0.42,\"behindM\":5.0}"),
            Map.entry(TargetPosition.class, "{\"xM\":1.2,\"yM\":0.3,\"distanceM\":1.0,\"angleRad\":0.24,"
                    + "\"seen\":true,\"method\":\"size\",\"xWorldM\":3.1,\"yWorldM\":-0.4}"),
            Map.entry(BlobList.class, "{\"width\":208,\"height\":160,\"blobs\":[{\"label\":\"pink\","
                    + "\"cx\":20.5,\"cy\":9.0,\"area\":189,\"x\":10,\"y\":5,\"w\":21,\"h\":9}]}"),
            Map.entry(TargetBearing.class, "{\"distanceM\":0.8,\"angleRad\":0.12,\"seen\":true}"),
            Map.entry(LinkStatus.class, "{\"connected\":true,\"stale\":false,\"sinceMs\":5300,\"interface\":"
                    + "\"robot\",\"detail\":\"all connections up\",\"connections\":{\"arcos\":true}}"),
            Map.entry(Climate.class, "{\"temperatureC\":21.5,\"humidityPct\":40.0}"),
            Map.entry(ComfortReport.class, "{\"temperatureC\":21.5,\"humidityPct\":40.0,\"lux\":300.0,"
                    + "\"score\":0.5,\"complaints\":[\"dark\"]}"),
            Map.entry(TeacherEmotion.class, "{\"emotion\":\"happy\",\"valence\":0.6,\"arousal\":0.4,"
                    + "\"words\":\"good dog\",\"intensity\":-18.0,\"source\":\"words\"}"),
            Map.entry(ButtonStates.class, "{\"backMiddle\":true,\"headTouch\":false}"),
            Map.entry(LampLevels.class, "{\"desk\":0.5,\"sofa\":0.0}"),
            Map.entry(LampCommand.class, "{\"state\":\"ON\",\"brightness\":127}"),
            Map.entry(CoverCommand.class, "{\"position\":75}"),
            Map.entry(SpeakerCommand.class, "{\"say\":\"dinner is ready\",\"volume\":50}"));

    private static final List<Case<?>> CASES = List.of(
            new Case<>(RangeScan.class, List.of(SCAN, SCAN_WITHOUT_POSES), RangeScan::fromRecord),
            new Case<>(PlanarPose.class, List.of(new PlanarPose(1, -2, 0.5)), r -> PlanarPose.fromRecord(r).orElseThrow()),
            new Case<>(CameraModel.class, List.of(new CameraModel(1.0, 0.75, 208, 160, 0.3)),
                    r -> CameraModel.fromRecord(r).orElseThrow()),
            new Case<>(HeadPose.class, List.of(new HeadPose(-0.2, 0.4, 0.1)), r -> HeadPose.fromRecord(r).orElseThrow()),
            new Case<>(MotionLimits.class, List.of(new MotionLimits(0.5, 1.2), new MotionLimits(0.5,
                    Double.POSITIVE_INFINITY), MotionLimits.NONE), MotionLimits::fromRecord),
            new Case<>(NearestObstacle.class, List.of(new NearestObstacle(0.42, 0.52, 0.41, 0.27, 2, "scan", true,
                    0.42, 5.0)), NearestObstacle::fromRecord),
            new Case<>(TargetPosition.class, List.of(new TargetPosition(1.2, 0.3, 1.0, 0.24, true, "size", null, 3.1,
                    -0.4), new TargetPosition(1.0, 0, 0.8, 0, false, "ground", 1.1, null, null)),
                    TargetPosition::fromRecord),
            new Case<>(BlobList.class, List.of(new BlobList(208, 160, List.of(new BlobList.Entry("pink", 20.5, 9.0,
                    189, 10, 5, 21, 9)))), r -> BlobList.fromRecord(r).orElseThrow()),
            new Case<>(TargetBearing.class, List.of(new TargetBearing(0.8, 0.12, true)), null),
            new Case<>(LinkStatus.class, List.of(new LinkStatus(true, false, 5300, "robot", "all connections up",
                    Map.of("arcos", true))), null),
            new Case<>(Climate.class, List.of(new Climate(21.5, 40.0), new Climate(null, 40.0)), Climate::fromRecord),
            new Case<>(ComfortReport.class, List.of(new ComfortReport(21.5, 40.0, 300.0, null, 0.5, List.of("dark")),
                    new ComfortReport(null, null, null, -30.0, 1, List.of())), null),
            new Case<>(TeacherEmotion.class, List.of(new TeacherEmotion("happy", 0.6, 0.4, "good dog", -18.0,
                    "words")), null),
            new Case<>(ButtonStates.class, List.of(new ButtonStates(orderedFlags())), null),
            new Case<>(LampLevels.class, List.of(new LampLevels(orderedLevels())), null),
            new Case<>(LampCommand.class, List.of(LampCommand.dimmedTo(127), LampCommand.ON, LampCommand.OFF), null),
            new Case<>(CoverCommand.class, List.of(new CoverCommand(75)), null),
            new Case<>(SpeakerCommand.class, List.of(new SpeakerCommand("dinner is ready", 50)), null));

    private static Map<String, Boolean> orderedFlags() {
        Map<String, Boolean> m = new java.util.LinkedHashMap<>();
        m.put("backMiddle", true);
        m.put("headTouch", false);
        return m;
    }

    private static Map<String, Double> orderedLevels() {
        Map<String, Double> m = new java.util.LinkedHashMap<>();
        m.put("desk", 0.5);
        m.put("sofa", 0.0);
        return m;
    }

    @Test
    void everyTypedRecordWritesExactlyTheFieldsItDeclares() {
        for (Case<?> c : CASES) {
            List<RecordField> declared = c.examples().get(0).layout().fields();
            if (declared.stream().anyMatch(f -> f.name().startsWith("<"))) {
                continue; // fields named at run time: the golden JSON checks them
            }
            List<String> required = declared.stream().filter(f -> !f.optional()).map(RecordField::name).toList();
            List<String> all = declared.stream().map(RecordField::name).toList();
            List<String> seen = new ArrayList<>();
            for (RecordForm example : c.examples()) {
                ObjectNode json = example.toJson();
                List<String> names = new ArrayList<>();
                json.fieldNames().forEachRemaining(names::add);
                assertThat(names).as(c.type().getSimpleName() + " " + json).containsAll(required);
                assertThat(all).as(c.type().getSimpleName() + " " + json).containsAll(names);
                seen.addAll(names);
            }
            assertThat(seen).as("the examples of " + c.type().getSimpleName() + " use every declared field")
                    .containsAll(all);
            assertThat(declared).as(c.type().getSimpleName() + " documents each field")
                    .allSatisfy(f -> assertThat(f.doc()).isNotBlank());
        }
    }

    @Test
    void theJsonOfATypedRecordIsTheJsonItWasWrittenAsBeforeItWasTyped() {
        for (Case<?> c : CASES) {
            assertThat(c.examples().get(0).toJson().toString()).as(c.type().getSimpleName())
                    .isEqualTo(GOLDEN.get(c.type()));
            assertThat(RecordValue.of(c.examples().get(0))).as("typed and JSON records are equal")
                    .isEqualTo(RecordValue.of(c.examples().get(0).toJson()))
                    .hasSameHashCodeAs(RecordValue.of(c.examples().get(0).toJson()));
        }
    }

    @Test
    void aTypedRecordReadBackFromItsJsonEqualsItself() {
        for (Case<?> c : CASES) {
            if (c.read() == null) {
                continue; // a record only sockets read
            }
            roundTrip(c);
        }
    }

    private static <T extends RecordForm> void roundTrip(Case<T> c) {
        for (T example : c.examples()) {
            RecordValue typed = RecordValue.of(example);
            assertThat(c.read().apply(typed)).as("inside the daemon the value itself").isSameAs(example);
            RecordValue fromJson = RecordValue.of(typed.json());
            T read = c.read().apply(fromJson);
            assertThat(read.toJson()).as(c.type().getSimpleName()).isEqualTo(example.toJson());
            assertThat(fromJson).isEqualTo(typed);
        }
    }
}
