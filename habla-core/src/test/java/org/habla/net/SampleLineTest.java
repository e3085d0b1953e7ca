package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

/** A sample line written straight from its payload is, byte for byte, the line its frame encodes to. */
class SampleLineTest {

    /** A form with a field of every kind a layout has, including fields named at run time. */
    record Everything(double d, Double maybe, int i, long l, boolean b, String s, double[] numbers, boolean[] flags,
            List<String> texts, JsonNode tree, Map<String, Object> zones) implements RecordForm {
        static final RecordLayout<Everything> LAYOUT = RecordLayout.of(Everything.class)
                .number("d", Everything::d).optionalNumber("maybe", Everything::maybe).integer("i", Everything::i)
                .longInteger("l", Everything::l).flag("b", Everything::b).text("s", Everything::s)
                .numbers("numbers", Everything::numbers).flags("flags", Everything::flags)
                .texts("texts", Everything::texts).array("tree", Everything::tree)
                .entries("<zone>", "number", Everything::zones).build();

        @Override
        public RecordLayout<?> layout() {
            return LAYOUT;
        }
    }

    private static String direct(Sample s) {
        return new String(EncodedFrame.sample("out", s).line(), StandardCharsets.UTF_8);
    }

    private static String throughTheFrame(Sample s) {
        return new String(EncodedFrame.of(SampleCodec.sampleFrame("out", s)).line(), StandardCharsets.UTF_8);
    }

    private static Sample sample(Payload p, long seq) {
        return new Sample(p, "m.out", seq, 1_795_950_519_077_732L + seq, seq % 3 == 0);
    }

    private static double number(Random r) {
        return switch (r.nextInt(8)) {
            case 0 -> Double.NaN;
            case 1 -> r.nextBoolean() ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
            case 2 -> r.nextInt(100);
            case 3 -> -0.0;
            case 4 -> Double.MIN_VALUE * r.nextInt(5);
            default -> (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(30) - 15);
        };
    }

    private static String text(Random r) {
        String[] parts = {"forward", "\"quoted\"", "\n", "\\", "ü", "狗", "\u0001", "", " ", "😀"};
        StringBuilder b = new StringBuilder();
        for (int k = r.nextInt(4); k > 0; k--) {
            b.append(parts[r.nextInt(parts.length)]);
        }
        return b.toString();
    }

    private static Everything everything(Random r) {
        double[] numbers = new double[r.nextInt(5)];
        for (int k = 0; k < numbers.length; k++) {
            numbers[k] = number(r);
        }
        var tree = JsonNodeFactory.instance.arrayNode();
        for (int k = r.nextInt(3); k > 0; k--) {
            tree.add(r.nextInt(4) == 0 ? number(r) : r.nextInt(10));
        }
        Map<String, Object> zones = new LinkedHashMap<>();
        for (int k = r.nextInt(4); k > 0; k--) {
            zones.put(r.nextInt(5) == 0 ? "d" : "zone" + r.nextInt(6), r.nextBoolean() ? number(r) : text(r));
        }
        return new Everything(number(r), r.nextBoolean() ? null : number(r), r.nextInt(), r.nextLong(),
                r.nextBoolean(), r.nextInt(5) == 0 ? null : text(r), r.nextInt(4) == 0 ? null : numbers,
                new boolean[] {r.nextBoolean(), true}, r.nextInt(4) == 0 ? null : List.of(text(r), text(r)),
                r.nextInt(3) == 0 ? null : tree, zones);
    }

    @Test
    void everyKindOfPayloadIsWrittenAsItsFrameIs() {
        Random r = new Random(11);
        List<Payload> payloads = new ArrayList<>();
        for (int k = 0; k < 2_000; k++) {
            double[] v = new double[r.nextInt(9)];
            for (int j = 0; j < v.length; j++) {
                v[j] = number(r);
            }
            payloads.add(new NumberValue(number(r)));
            payloads.add(VectorValue.of(v));
            payloads.add(new TextValue(text(r)));
            payloads.add(RecordValue.of(everything(r)));
            payloads.add(RecordValue.builder().put("distanceM", number(r)).put("name", text(r))
                    .put("valid", r.nextBoolean()).put("count", r.nextLong()).build());
        }
        int typedWritten = 0;
        for (int k = 0; k < payloads.size(); k++) {
            Sample s = sample(payloads.get(k), k);
            assertThat(direct(s)).as(payloads.get(k).toString()).isEqualTo(throughTheFrame(s));
            typedWritten += direct(s).contains("\"numbers\"") ? 1 : 0;
        }
        assertThat(typedWritten).as("typed records written with their arrays").isGreaterThan(500);
    }

    @Test
    void aTypedRecordIsWrittenWithoutMakingItsJson() {
        Everything e = new Everything(1.5, null, 3, 4L, true, "x", new double[] {Double.NaN, 2}, new boolean[] {true},
                List.of("a"), null, Map.of("zone1", 0.5));
        RecordValue r = RecordValue.of(e);
        String line = direct(sample(r, 1));
        assertThat(line).contains("\"value\":{\"d\":1.5,\"i\":3,\"l\":4,\"b\":true,\"s\":\"x\",\"numbers\":[null,2.0],"
                + "\"flags\":[true],\"texts\":[\"a\"],\"zone1\":0.5}}\n");
        assertThat(r.hasJson()).as("the record's JSON was made").isFalse();
    }

    @Test
    void audioStillGoesThroughItsFrameWithItsBody() {
        Sample s = sample(AudioChunk.of(new AudioFormat(16_000, 1, 16), new byte[] {1, 2, 3, 4}), 1);
        EncodedFrame e = EncodedFrame.sample("out", s);
        assertThat(e.body()).containsExactly(1, 2, 3, 4);
        assertThat(new String(e.line(), StandardCharsets.UTF_8)).isEqualTo(throughTheFrame(s)).contains("\"bytes\":4");
    }
}
