package org.habla.methods.audio;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;

class FftTest {

    @Test
    void powerSpectrumMatchesADirectFourierSum() {
        Random r = new Random(3);
        double[] x = new double[100];
        for (int i = 0; i < x.length; i++) {
            x[i] = r.nextGaussian();
        }
        double[] w = Fft.hann(x.length);
        double[] p = new Fft(128).power(x, w);
        for (int k = 0; k <= 64; k++) {
            double re = 0;
            double im = 0;
            for (int n = 0; n < x.length; n++) {
                re += x[n] * w[n] * Math.cos(2 * Math.PI * k * n / 128);
                im -= x[n] * w[n] * Math.sin(2 * Math.PI * k * n / 128);
            }
            assertThat(p[k]).as("bin %d", k).isCloseTo(re * re + im * im, within(1e-9 * (1 + re * re + im * im)));
        }
    }

    @Test
    void sizeMustBeAPowerOfTwoAndTheFrameMustFit() {
        assertThatThrownBy(() -> new Fft(100)).hasMessageContaining("power of two");
        assertThatThrownBy(() -> new Fft(64).power(new double[65], new double[65])).hasMessageContaining("does not fit");
        assertThat(Fft.sizeFor(513)).isEqualTo(1024);
    }
}
