package org.habla.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.atomic.AtomicInteger;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.net.Frame;
import org.habla.net.SampleCodec;
import org.junit.jupiter.api.Test;

class RecordValueTest {

    /** A typed record that counts how often its JSON is made. */
    record Point(double xM, String note, AtomicInteger madeJson) implements RecordForm {
        static final RecordLayout<Point> LAYOUT = RecordLayout.of(Point.class)
                .number("xM", Point::xM).unit("m").frame("robot frame: x forward").doc("how far ahead")
                .text("note", Point::note).optional().doc("what is there")
                .build();

        @Override
        public RecordLayout<Point> layout() {
            return LAYOUT;
        }

        @Override
        public ObjectNode toJson() {
            madeJson.incrementAndGet();
            return LAYOUT.json(this);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Point p && Double.compare(p.xM, xM) == 0 && java.util.Objects.equals(p.note, note);
        }

        @Override
        public int hashCode() {
            return java.util.Objects.hash(xM, note);
        }
    }

    record Tilt(double tiltRad) implements RecordForm {
        static final RecordLayout<Tilt> LAYOUT = RecordLayout.of(Tilt.class).number("tiltRad", Tilt::tiltRad).build();

        @Override
        public RecordLayout<Tilt> layout() {
            return LAYOUT;
        }
    }

    @Test
    void aTypedRecordGivesBackItsOwnValueAndMakesNoJsonUntilAnEdgeAsks() {
        AtomicInteger made = new AtomicInteger();
        Point p = new Point(1.5, null, made);
        RecordValue r = RecordValue.of(p);

        assertThat(r.form(Point.class)).containsSame(p);
        assertThat(r.as(Point.class, x -> null)).isSameAs(p);
        assertThat(r.form(Tilt.class)).isEmpty();
        assertThat(made).hasValue(0);

        assertThat(r.number("xM")).isEqualTo(1.5);
        assertThat(r.get("xM").doubleValue()).isEqualTo(1.5);
        assertThat(r.has("note")).isFalse();
        assertThat(r.get("note").isMissingNode()).isTrue();
        assertThat(r).isEqualTo(RecordValue.of(new Point(1.5, null, made)));
        assertThat(r.hashCode()).isEqualTo(RecordValue.of(new Point(1.5, null, made)).hashCode());
        assertThat(made).as("accessors, equals and hashCode read the form, not its JSON").hasValue(0);

        assertThat(r.json().toString()).isEqualTo("{\"xM\":1.5}");
        assertThat(r.jsonView().toString()).isEqualTo("{\"xM\":1.5}");
        assertThat(made).as("the JSON is made once").hasValue(1);
    }

    /** A count that a record may lack. */
    record Count(Long items) implements RecordForm {
        static final RecordLayout<Count> LAYOUT = RecordLayout.of(Count.class)
                .optionalLongInteger("items", Count::items).doc("how many, when known").build();

        @Override
        public RecordLayout<Count> layout() {
            return LAYOUT;
        }
    }

    @Test
    void anOptionalWholeNumberIsWrittenAsALongOrLeftOut() {
        RecordValue some = RecordValue.of(new Count(5_000_000_000L));
        assertThat(some.jsonView().toString()).isEqualTo("{\"items\":5000000000}");
        assertThat(some).isEqualTo(RecordValue.builder().put("items", 5_000_000_000L).build());
        assertThat(RecordValue.of(new Count(3L))).isEqualTo(RecordValue.builder().put("items", 3).build())
                .hasSameHashCodeAs(RecordValue.builder().put("items", 3).build());
        assertThat(RecordValue.of(new Count(null)).jsonView().toString()).isEqualTo("{}");
        assertThat(RecordValue.of(new Count(null)).has("items")).isFalse();
        assertThat(Count.LAYOUT.fields().get(0).optional()).isTrue();
        assertThat(Count.LAYOUT.fields().get(0).type()).isEqualTo("integer");
    }

    @Test
    void aRecordThatCameAsJsonIsReadByTheFormsReader() {
        RecordValue r = RecordValue.of(JsonNodeFactory.instance.objectNode().put("tiltRad", 0.25));
        assertThat(r.form(Tilt.class)).isEmpty();
        assertThat(r.as(Tilt.class, x -> new Tilt(x.number("tiltRad")))).isEqualTo(new Tilt(0.25));
        assertThat(r).isEqualTo(RecordValue.of(new Tilt(0.25))).hasSameHashCodeAs(RecordValue.of(new Tilt(0.25)));
    }

    @Test
    void aTypedRecordIsWrittenOnTheWireExactlyAsTheSameRecordBuiltAsJson() {
        RecordValue typed = RecordValue.of(new Point(2.0, "door", new AtomicInteger()));
        RecordValue json = RecordValue.builder().put("xM", 2.0).put("note", "door").build();
        Sample a = new Sample(typed, "p", 10, 7, false);
        Sample b = new Sample(json, "p", 10, 7, false);
        Frame fa = SampleCodec.sampleFrame("p", a);
        Frame fb = SampleCodec.sampleFrame("p", b);
        assertThat(fa.header().toString()).isEqualTo(fb.header().toString()).contains("\"note\":\"door\"");
    }

    @Test
    void aBuilderThatGoesOnAfterBuildingDoesNotChangeWhatItBuilt() {
        RecordValue.Builder b = RecordValue.builder().put("a", 1.0);
        RecordValue first = b.build();
        RecordValue second = b.put("b", 2.0).build();
        assertThat(first.has("b")).isFalse();
        assertThat(second.has("a")).isTrue();
        assertThat(second.number("b")).isEqualTo(2.0);
    }

    @Test
    void aTypedRecordAndTheSameRecordBuiltAsJsonAreEqualAndHashAlike() {
        RecordValue typed = RecordValue.of(new Point(2.0, "door", new AtomicInteger()));
        RecordValue json = RecordValue.builder().put("xM", 2.0).put("note", "door").build();
        assertThat(typed).isEqualTo(json).hasSameHashCodeAs(json);
        assertThat(json).isEqualTo(typed);
        assertThat(typed).isNotEqualTo(RecordValue.builder().put("xM", 2.0).build());
    }

    @Test
    void aShapeNamingALayoutListsItsFieldsWithUnitFrameAndMeaning() {
        Shape s = Shape.record("a point", Point.LAYOUT);
        assertThat(s.fields()).containsExactly("xM", "note");
        assertThat(s.form()).isEqualTo(Point.class);
        assertThat(s.kind()).isEqualTo(PayloadKind.RECORD);
        assertThat(s.recordFields()).extracting(Object::toString).containsExactly(
                "xM (number, m; robot frame: x forward): how far ahead",
                "note (text, optional): what is there");
        assertThatThrownBy(() -> RecordLayout.of(Tilt.class).build()).hasMessageContaining("declares no fields");
        assertThatThrownBy(() -> RecordLayout.of(Tilt.class).number("a", t -> 1).number("a", t -> 2).build())
                .hasMessageContaining("declares field a twice");
    }

    /** Emits what it is given, as a typed record of whatever form the sample holds, on a {@code Point} port. */
    static final class PointSource extends ProcessingMethod {
        private final Output<RecordValue> out = output(OutputPort.of("out", RecordValue.class,
                Shape.record("points", Point.LAYOUT)));

        PointSource() {
            input(InputPort.of("in", RecordValue.class, Delivery.queue(4)), (value, sample) -> emit(out, value));
        }
    }

    @Test
    void aMethodThatEmitsAnotherFormOnATypedPortFailsSayingWhich() {
        MethodHarness h = MethodHarness.started("points", new PointSource());
        h.push("in", RecordValue.of(new Point(1, null, new AtomicInteger())));
        h.push("in", RecordValue.builder().put("xM", 3.0).build()); // JSON from an edge is let through
        assertThat(h.values("out")).hasSize(2);
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);

        h.expectFailure().push("in", RecordValue.of(new Tilt(0.1)));
        assertThat(h.values("out")).hasSize(2);
        assertThat(h.state()).isEqualTo(MethodState.FAILED);
        assertThat(h.failure()).contains("carries Point records, not Tilt");
    }
}
