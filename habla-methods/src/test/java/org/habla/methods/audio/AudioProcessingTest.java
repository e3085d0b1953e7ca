package org.habla.methods.audio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Random;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class AudioProcessingTest {

    private static final int RATE = 16_000;
    private static final AudioFormat STEREO_16K = new AudioFormat(RATE, 2, 16);

    private static MethodHarness started() {
        return MethodHarness.started("audio", new AudioProcessing(AudioProcessingParams.defaults()));
    }

    private static List<RecordValue> features(MethodHarness h) {
        return h.values("features").stream().map(RecordValue.class::cast).toList();
    }

    @Test
    void pitchOfSynthesisedTonesIsWithinTwoPercent() {
        double[] tones = {82.41, 110, 196, 261.63, 440, 523.25, 659.25, 783.99, 1046.5};
        AudioFormat[] formats = {AudioFormat.MONO_16K, STEREO_16K, new AudioFormat(44_100, 1, 16)};
        for (AudioFormat format : formats) {
            for (double hz : tones) {
                MethodHarness h = started();
                Signals.stream(h, "audio", Signals.tone(hz, 0.3, 0.5, format.sampleRateHz()), format, 20, 0);
                List<RecordValue> f = features(h);
                assertThat(f).hasSizeGreaterThan(10);
                double worst = 0;
                for (RecordValue r : f) {
                    assertThat(r.get("voiced").booleanValue()).as("%s Hz at %s voiced", hz, format).isTrue();
                    worst = Math.max(worst, Math.abs(r.number("pitchHz") / hz - 1));
                }
                assertThat(worst).as("worst pitch error of %s Hz at %s", hz, format).isLessThan(0.02);
            }
        }
    }

    @Test
    void levelOfASineIsItsRmsInDecibelsOfFullScale() {
        MethodHarness h = started();
        Signals.stream(h, "audio", Signals.tone(1000, 0.5, 0.3, RATE), AudioFormat.MONO_16K, 20, 0);
        RecordValue f = (RecordValue) h.last("features");
        assertThat(f.number("rms")).isCloseTo(0.5 / Math.sqrt(2), within(0.005));
        assertThat(f.number("db")).isCloseTo(20 * Math.log10(0.5 / Math.sqrt(2)), within(0.1));
    }

    @Test
    void spectrumPutsAToneInItsBandAndAddsUpToTheFramePower() {
        MethodHarness h = started();
        Signals.stream(h, "audio", Signals.add(Signals.tone(3100, 0.4, 0.3, RATE),
                Signals.noise(0.001, 0.3, RATE, new Random(2))), AudioFormat.MONO_16K, 20, 0);
        RecordValue f = (RecordValue) h.last("features");
        double[] bands = new double[f.get("spectrum").size()];
        double total = 0;
        int strongest = 0;
        for (int b = 0; b < bands.length; b++) {
            bands[b] = f.get("spectrum").get(b).doubleValue();
            total += Math.pow(10, bands[b] / 10);
            strongest = bands[b] > bands[strongest] ? b : strongest;
        }
        assertThat(bands).hasSize(16);
        assertThat(strongest).as("3100 Hz lies in the 3000-3500 Hz band").isEqualTo(6);
        assertThat(bands[strongest] - bands[12]).isGreaterThan(40);
        assertThat(10 * Math.log10(total)).isCloseTo(f.number("db"), within(0.5));
    }

    @Test
    void noiseAndSilenceAreUnvoicedAndMakeNoSegments() {
        MethodHarness h = started();
        double[] x = Signals.concat(Signals.silence(1, RATE), Signals.noise(0.05, 3, RATE, new Random(5)));
        Signals.stream(h, "audio", x, AudioFormat.MONO_16K, 20, 0);
        List<RecordValue> f = features(h);
        long voiced = f.stream().filter(r -> r.get("voiced").booleanValue()).count();
        System.out.printf("audio-processing: %d of %d noise/silence frames called voiced%n", voiced, f.size());
        assertThat(voiced).isLessThanOrEqualTo(f.size() / 50);
        assertThat(f.get(5).number("db")).isEqualTo(-120);
        assertThat(f.get(5).number("pitchHz")).isZero();
        // the noise starts loud against digital silence: one long segment at most, then the floor adapts
        long t0 = System.nanoTime();
        Signals.stream(h.clear(), "audio", Signals.noise(0.05, 3, RATE, new Random(6)), AudioFormat.MONO_16K, 20,
                4_000_000);
        double ms = (System.nanoTime() - t0) / 1e6;
        System.out.printf("audio-processing: 3 s of audio analysed in %.0f ms (%.0f times real time)%n", ms,
                3000 / ms);
        assertThat(h.values("segments")).isEmpty();
    }

    @Test
    void segmentsCoverEachToneWithPrerollAndHangover() {
        MethodHarness h = started();
        Random r = new Random(9);
        double[] x = Signals.concat(
                Signals.noise(0.003, 1.5, RATE, r),
                Signals.add(Signals.tone(440, 0.2, 0.5, RATE), Signals.noise(0.003, 0.5, RATE, r)),
                Signals.noise(0.003, 1.0, RATE, r),
                Signals.add(Signals.tone(700, 0.2, 0.8, RATE), Signals.noise(0.003, 0.8, RATE, r)),
                Signals.noise(0.003, 1.0, RATE, r),
                Signals.add(Signals.tone(900, 0.3, 0.03, RATE), Signals.noise(0.003, 0.03, RATE, r)),
                Signals.noise(0.003, 1.0, RATE, r));
        Signals.stream(h, "audio", x, STEREO_16K, 20, 0);
        List<Payload> segs = h.values("segments");
        assertThat(segs).as("two tones; the 30 ms click is dropped").hasSize(2);
        double[] expectS = {0.5 + 0.15 + 0.3, 0.8 + 0.15 + 0.3};
        for (int i = 0; i < 2; i++) {
            AudioChunk c = (AudioChunk) segs.get(i);
            assertThat(c.format()).isEqualTo(AudioFormat.MONO_16K);
            assertThat(c.frameCount() / (double) RATE).isCloseTo(expectS[i], within(0.1));
        }
    }

    @Test
    void aChangeOfFormatRestartsTheAnalysisAndUnusableAudioIsIgnored() {
        MethodHarness h = started();
        Signals.stream(h, "audio", Signals.tone(440, 0.3, 0.3, 8000), new AudioFormat(8000, 1, 16), 20, 0);
        Signals.stream(h, "audio", Signals.tone(440, 0.3, 0.3, 1000), new AudioFormat(1000, 1, 16), 20, 0);
        int before = h.values("features").size();
        Signals.stream(h, "audio", Signals.tone(330, 0.3, 0.3, RATE), STEREO_16K, 20, 0);
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);
        assertThat(h.values("features").size()).isGreaterThan(before);
        assertThat(((RecordValue) h.last("features")).number("pitchHz")).isCloseTo(330, within(330 * 0.02));
    }
}
