package org.habla.methods.voice;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class SpeechTest {

    private static final int RATE = 16_000;

    private static double[] joined(List<Payload> chunks) {
        int n = chunks.stream().mapToInt(c -> ((AudioChunk) c).frameCount()).sum();
        double[] out = new double[n];
        int at = 0;
        for (Payload c : chunks) {
            double[] s = ((AudioChunk) c).channel(0);
            System.arraycopy(s, 0, out, at, s.length);
            at += s.length;
        }
        return out;
    }

    /** Frequency over [fromMs, toMs) by counting rising zero crossings. */
    private static double hz(double[] x, int fromMs, int toMs) {
        int from = fromMs * RATE / 1000;
        int to = toMs * RATE / 1000;
        int first = -1;
        int last = -1;
        int crossings = 0;
        for (int i = from + 1; i < to; i++) {
            if (x[i - 1] < 0 && x[i] >= 0) {
                if (first < 0) {
                    first = i;
                } else {
                    crossings++;
                }
                last = i;
            }
        }
        return crossings * (double) RATE / (last - first);
    }

    private static MethodHarness started(SpeechParams p) {
        return MethodHarness.started("speech", new Speech(p));
    }

    @Test
    void happyRisesThroughAMajorChordAndSadFallsSlowly() {
        MethodHarness h = started(SpeechParams.defaults());
        h.push("text", new TextValue("happy"));
        double[] happy = joined(h.values("audio"));
        assertThat(happy.length).isEqualTo(440 * RATE / 1000);
        assertThat(hz(happy, 10, 110)).isCloseTo(523.25, within(8.0));
        assertThat(hz(happy, 130, 230)).isCloseTo(659.25, within(8.0));
        assertThat(hz(happy, 250, 430)).isCloseTo(783.99, within(8.0));
        h.clear();
        h.push("text", new TextValue("sad"));
        double[] sad = joined(h.values("audio"));
        assertThat(sad.length).isEqualTo(1100 * RATE / 1000);
        assertThat(hz(sad, 10, 290)).isCloseTo(440, within(8.0));
        assertThat(hz(sad, 900, 1090)).isLessThan(260);
    }

    @Test
    void theSameTextAlwaysSoundsTheSameAndOtherWordsChirpDifferently() {
        MethodHarness a = started(SpeechParams.defaults());
        MethodHarness b = started(SpeechParams.defaults());
        a.push("text", new TextValue("hello robot"));
        b.push("text", new TextValue("hello robot"));
        assertThat(a.values("audio")).isEqualTo(b.values("audio"));
        b.clear();
        b.push("text", new TextValue("hello world"));
        assertThat(b.values("audio")).isNotEqualTo(a.values("audio"));
        double[] x = joined(a.values("audio"));
        double peak = 0;
        for (double v : x) {
            peak = Math.max(peak, Math.abs(v));
        }
        assertThat(peak).isCloseTo(0.5, within(0.01));
        assertThat(x.length).as("300 ms + 60 ms rest + 300 ms").isEqualTo(660 * RATE / 1000);
    }

    @Test
    void audioComesInBoundedMono16BitChunksAndLongTextIsCut() {
        MethodHarness h = started(ParamsJson.of(SpeechParams.class, "{\"chunkMs\": 100, \"maxChars\": 12}"));
        h.push("text", new TextValue("happy happy happy"));
        List<Payload> chunks = h.values("audio");
        for (Payload c : chunks) {
            assertThat(((AudioChunk) c).format()).isEqualTo(AudioFormat.MONO_16K);
            assertThat(((AudioChunk) c).frameCount()).isLessThanOrEqualTo(1600);
        }
        assertThat(joined(chunks).length).as("only the first 12 characters: two words").isEqualTo((440 * 2 + 60) * RATE / 1000);
        MethodHarness tones = started(SpeechParams.defaults());
        tones.push("text", new TextValue("1000:50 0:50 2000:50"));
        double[] spelled = joined(tones.values("audio"));
        assertThat(spelled.length).isEqualTo(150 * RATE / 1000);
        assertThat(hz(spelled, 100, 150)).isCloseTo(2000, within(40.0));
    }

    @Test
    void anEmotionIsSaidWhenItChangesAndNotTooOften() {
        MethodHarness h = started(SpeechParams.defaults());
        RecordValue happy = RecordValue.builder().put("emotion", "happy").put("valence", 1.0).build();
        RecordValue sad = RecordValue.builder().put("emotion", "sad").put("valence", -1.0).build();
        h.push("emotion", happy);
        int once = h.values("audio").size();
        assertThat(once).isGreaterThan(0);
        h.push("emotion", happy);
        h.advanceMillis(500);
        h.push("emotion", sad);
        assertThat(h.values("audio")).as("same emotion, then too soon").hasSize(once);
        h.advanceMillis(2000);
        h.push("emotion", sad);
        assertThat(h.values("audio").size()).isGreaterThan(once);
        int twice = h.values("audio").size();
        h.advanceMillis(3000);
        h.push("emotion", RecordValue.builder().put("emotion", "neutral").build());
        assertThat(h.values("audio")).as("neutral is not said").hasSize(twice);
        h.push("emotion", sad);
        assertThat(h.values("audio").size()).as("sad again after a neutral").isGreaterThan(twice);
        h.push("emotion", RecordValue.builder().put("emotion", 3).build());
        h.push("emotion", RecordValue.builder().put("feeling", "odd").build());
    }
}
