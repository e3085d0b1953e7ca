package org.habla.methods.audio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class UtteranceGateTest {

    private static final int RATE = 16_000;

    /** Talk-like background: noise whose loudness comes and goes four times a second, as syllables do. */
    private static double[] talk(double sigma, double seconds, Random r) {
        double[] x = Signals.noise(sigma, seconds, RATE, r);
        for (int i = 0; i < x.length; i++) {
            double t = i / (double) RATE;
            x[i] *= 0.3 + 0.7 * Math.abs(Math.sin(Math.PI * 4 * t + Math.sin(t)));
        }
        return x;
    }

    private static List<double[]> cut(double[] x, int blockMs) {
        UtteranceGate gate = new UtteranceGate(RATE, AudioProcessingParams.defaults().gate());
        List<double[]> out = new ArrayList<>();
        int block = RATE * blockMs / 1000;
        for (int at = 0; at < x.length; at += block) {
            out.addAll(gate.offer(java.util.Arrays.copyOfRange(x, at, Math.min(x.length, at + block))));
        }
        return out;
    }

    @Test
    void aVoiceOverOtherPeoplesTalkIsCutAloneWithItsPrerollAndHangover() {
        Random r = new Random(3);
        double[] voice = Signals.add(Signals.tone(220, 0.1, 0.6, RATE), Signals.tone(660, 0.05, 0.6, RATE));
        double[] x = Signals.concat(talk(0.02, 4, r), Signals.add(voice, talk(0.02, 0.6, r)), talk(0.02, 3, r));
        List<double[]> segments = cut(x, 32);
        assertThat(segments).as("one segment: the voice, not the talk around it").hasSize(1);
        double prerollS = AudioProcessingParams.defaults().prerollMs() / 1000;
        double hangoverS = AudioProcessingParams.defaults().hangoverMs() / 1000;
        assertThat(segments.get(0).length / (double) RATE).isCloseTo(0.6 + prerollS + hangoverS, within(0.08));
    }

    @Test
    void anEchoDyingAwayDoesNotHoldTheGateOpen() {
        double[] burst = Signals.tone(300, 0.3, 0.4, RATE);
        double[] tail = new double[RATE * 2];
        for (int i = 0; i < tail.length; i++) {
            tail[i] = 0.3 * Math.exp(-i / (0.25 * RATE)) * Math.sin(2 * Math.PI * 300 * i / RATE);
        }
        double[] x = Signals.concat(Signals.silence(1, RATE), burst, tail, Signals.silence(1, RATE));
        List<double[]> segments = cut(x, 20);
        assertThat(segments).hasSize(1);
        // the tail is 30 dB down after 0.86 s: the segment ends about a hangover later, not when it reaches digital silence
        assertThat(segments.get(0).length / (double) RATE).isLessThan(0.2 + 0.4 + 0.9 + 0.25);
    }
}
