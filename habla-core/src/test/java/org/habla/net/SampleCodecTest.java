package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.List;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class SampleCodecTest {

    private static final List<Payload> EVERY_KIND = List.of(
            new NumberValue(-0.25),
            VectorValue.of(0.5, 1.0, 4.75),
            new TextValue("forward \"quoted\"\n"),
            RecordValue.builder().put("distanceM", 1.5).put("angleRad", -0.3).put("visible", true).build(),
            AudioChunk.of(new AudioFormat(16_000, 2, 16), new byte[] {1, 2, '\n', 4, 5, 6, 7, 8}),
            ImageFrame.of(2, 1, "bgr8", new byte[] {'\n', 0, 1, 2, 3, (byte) 0xff}));

    /** Encodes, writes, reads and decodes, as a peer would. */
    private static Frame overTheWire(Frame frame) throws Exception {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(wire);
        w.write(frame);
        w.flush();
        return new FrameReader(new TrickleInputStream(wire.toByteArray()), 4_096, 4_096).read();
    }

    private static Frame parsed(String line) throws Exception {
        return new FrameReader(new ByteArrayInputStream(line.getBytes(UTF_8)), 4_096, 4_096).read();
    }

    @Test
    void everyKindSurvivesARoundTripForItsOwnKindAndForAny() throws Exception {
        for (Payload p : EVERY_KIND) {
            Frame f = overTheWire(SampleCodec.withValue(JsonNodeFactory.instance.objectNode(), p));
            assertThat(SampleCodec.value(f, p.kind())).as(p.toString()).isEqualTo(p);
            assertThat(SampleCodec.value(f, PayloadKind.ANY)).as(p.toString()).isEqualTo(p);
        }
    }

    @Test
    void aSampleLineCarriesItsFieldsInTheDocumentedOrder() throws Exception {
        Sample s = new Sample(RecordValue.builder().put("distanceM", 2.0).build(), "tracker.value", 17,
                1_763_798_400_123_456L, false);
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(wire);
        w.send(SampleCodec.sampleFrame("value", s));
        assertThat(wire.toString(UTF_8)).isEqualTo("{\"type\":\"sample\",\"output\":\"value\",\"seq\":17,"
                + "\"t\":1763798400123456,\"stale\":false,\"kind\":\"record\",\"value\":{\"distanceM\":2.0}}\n");
        Sample back = SampleCodec.sample(parsed(wire.toString(UTF_8)), "peer");
        assertThat(back).isEqualTo(new Sample(s.payload(), "peer", 17, 1_763_798_400_123_456L, false));
    }

    @Test
    void binarySampleLinesDeclareTheirFormatAndLength() throws Exception {
        AudioChunk audio = AudioChunk.of(AudioFormat.MONO_16K, new byte[320]);
        Frame f = SampleCodec.sampleFrame("audio", new Sample(audio, "mic.audio", 1, 5, true));
        assertThat(f.header().toString()).contains("\"kind\":\"audio\",\"rateHz\":16000,\"channels\":1,\"bits\":16,"
                + "\"bytes\":320");
        assertThat(f.header().has("value")).isFalse();
        assertThat(overTheWire(f).body()).hasSize(320);
        Frame image = SampleCodec.sampleFrame("camera", new Sample(ImageFrame.of(4, 3, "jpeg", new byte[] {1, 2}),
                "cam.image", 2, 5, false));
        assertThat(image.header().toString()).contains("\"kind\":\"image\",\"width\":4,\"height\":3,"
                + "\"encoding\":\"jpeg\",\"bytes\":2");
    }

    @Test
    void nonFiniteNumbersTravelAsNullAndReadBackAsNaN() throws Exception {
        Frame n = SampleCodec.withValue(JsonNodeFactory.instance.objectNode(), new NumberValue(Double.POSITIVE_INFINITY));
        assertThat(n.header().get("value").isNull()).isTrue();
        assertThat(((NumberValue) SampleCodec.value(overTheWire(n), PayloadKind.NUMBER)).value()).isNaN();
        Frame v = SampleCodec.withValue(JsonNodeFactory.instance.objectNode(), VectorValue.of(1, Double.NaN));
        assertThat(v.header().get("value").toString()).isEqualTo("[1.0,null]");
        ObjectNode fields = JsonNodeFactory.instance.objectNode();
        fields.putObject("inner").put("x", Double.NaN);
        Frame r = SampleCodec.withValue(JsonNodeFactory.instance.objectNode(), RecordValue.of(fields));
        assertThat(r.header().get("value").toString()).isEqualTo("{\"inner\":{\"x\":null}}");
    }

    @Test
    void clientValuesInEveryJsonFormAreAccepted() throws Exception {
        assertThat(SampleCodec.value(parsed("{\"value\":3}\n"), PayloadKind.NUMBER)).isEqualTo(new NumberValue(3));
        assertThat(SampleCodec.value(parsed("{\"value\":[1,2.5]}\n"), PayloadKind.VECTOR))
                .isEqualTo(VectorValue.of(1, 2.5));
        assertThat(SampleCodec.value(parsed("{\"value\":\"left\"}\n"), PayloadKind.TEXT))
                .isEqualTo(new TextValue("left"));
        assertThat(SampleCodec.value(parsed("{\"value\":{\"a\":[1]}}\n"), PayloadKind.RECORD).toString())
                .isEqualTo("RecordValue{\"a\":[1]}");
    }

    @Test
    void valuesOfTheWrongShapeAreRejectedSayingWhatWasExpected() {
        assertBadValue("{\"value\":\"3\"}\n", PayloadKind.NUMBER, "expected a number");
        assertBadValue("{\"value\":[1,\"x\"]}\n", PayloadKind.VECTOR, "element 1");
        assertBadValue("{\"value\":{}}\n", PayloadKind.VECTOR, "expected an array of numbers");
        assertBadValue("{\"value\":7}\n", PayloadKind.TEXT, "expected a string");
        assertBadValue("{\"value\":[]}\n", PayloadKind.RECORD, "expected a JSON object");
        assertBadValue("{\"op\":\"write\"}\n", PayloadKind.TEXT, "no \"value\"");
        assertBadValue("{\"kind\":\"text\",\"value\":\"a\"}\n", PayloadKind.VECTOR, "got \"kind\": \"text\"");
        assertBadValue("{\"kind\":\"blob\",\"value\":1}\n", PayloadKind.ANY, "unknown payload kind 'blob'");
        assertBadValue("{\"kind\":\"audio\",\"rateHz\":16000,\"channels\":1,\"bits\":16}\n", PayloadKind.AUDIO,
                "\"bytes\" is missing");
        assertBadValue("{\"kind\":\"audio\",\"rateHz\":16000,\"channels\":1,\"bits\":12,\"bytes\":0}\n",
                PayloadKind.AUDIO, "bitsPerSample must be 8 or 16");
        assertBadValue("{\"kind\":\"audio\",\"rateHz\":16000,\"channels\":1,\"bits\":16,\"bytes\":3}\nabc",
                PayloadKind.AUDIO, "not a whole number of 2-byte frames");
        assertBadValue("{\"kind\":\"image\",\"width\":2,\"height\":2,\"encoding\":\"gray8\",\"bytes\":3}\nabc",
                PayloadKind.IMAGE, "needs 4 bytes");
        assertBadValue("{\"kind\":\"image\",\"width\":\"2\",\"height\":2,\"encoding\":\"jpeg\",\"bytes\":1}\na",
                PayloadKind.IMAGE, "\"width\" must be a whole number");
    }

    private static void assertBadValue(String wire, PayloadKind kind, String message) {
        assertThatThrownBy(() -> SampleCodec.value(parsed(wire), kind))
                .isInstanceOfSatisfying(FrameException.class, e -> {
                    assertThat(e.code()).isEqualTo("bad_value");
                    assertThat(e.fatal()).isFalse();
                })
                .hasMessageContaining(message);
    }
}
