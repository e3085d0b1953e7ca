package org.habla.methods.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;
import org.habla.method.Shape;
import org.habla.methods.gaze.HeadPose;
import org.habla.methods.motion.MotionLimits;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

/**
 * The method library's typed records: each one's JSON has the fields its {@link RecordForm.Fields} declares
 * (every required one, no other), and a record read back from that JSON, as a method reads one that came from a
 * socket, a recording or a worker, equals the typed one it was written from.
 */
class RecordFormsTest {

    private record Case<T extends RecordForm>(Class<T> type, List<T> examples, Function<RecordValue, T> read) {
    }

    private static final RangeScan SCAN = new RangeScan(new double[] {0.8, 5.0}, new boolean[] {true, false},
            new double[] {5.0, 5.0}, List.of(new PlanarPose(0.069, 0.136, 1.5708), new PlanarPose(0.1, -0.1, -0.5)));
    private static final RangeScan SCAN_WITHOUT_POSES = new RangeScan(new double[] {1.25}, new boolean[] {true},
            new double[] {3.0}, List.of());

    private static final List<Case<?>> CASES = List.of(
            new Case<>(RangeScan.class, List.of(SCAN, SCAN_WITHOUT_POSES), RangeScan::fromRecord),
            new Case<>(PlanarPose.class, List.of(new PlanarPose(1, -2, 0.5)), r -> PlanarPose.fromRecord(r).orElseThrow()),
            new Case<>(CameraModel.class, List.of(new CameraModel(1.0, 0.75, 208, 160, 0.3)),
                    r -> CameraModel.fromRecord(r).orElseThrow()),
            new Case<>(HeadPose.class, List.of(new HeadPose(-0.2, 0.4, 0.1)), r -> HeadPose.fromRecord(r).orElseThrow()),
            new Case<>(MotionLimits.class, List.of(new MotionLimits(0.5, 1.2), new MotionLimits(0.5,
                    Double.POSITIVE_INFINITY), MotionLimits.NONE), MotionLimits::fromRecord));

    @Test
    void everyTypedRecordWritesExactlyTheFieldsItDeclares() {
        for (Case<?> c : CASES) {
            String[] declared = c.type().getAnnotation(RecordForm.Fields.class).value();
            List<String> required = Arrays.stream(declared).filter(f -> !f.endsWith("?")).toList();
            List<String> all = Shape.fieldsOf(c.type());
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
        }
    }

    @Test
    void aTypedRecordReadBackFromItsJsonEqualsItself() {
        for (Case<?> c : CASES) {
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
