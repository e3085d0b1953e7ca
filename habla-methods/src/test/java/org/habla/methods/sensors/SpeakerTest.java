package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Payload;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class SpeakerTest {

    private static AudioChunk stereo(int frames, double left, double right) {
        byte[] pcm = new byte[frames * 4];
        for (int i = 0; i < frames; i++) {
            short l = (short) Math.round(left * 32767);
            short r = (short) Math.round(right * 32767);
            pcm[4 * i] = (byte) l;
            pcm[4 * i + 1] = (byte) (l >> 8);
            pcm[4 * i + 2] = (byte) r;
            pcm[4 * i + 3] = (byte) (r >> 8);
        }
        return AudioChunk.of(new AudioFormat(16_000, 2, 16), pcm);
    }

    @Test
    void stereoIsMixedToMonoWithTheGainAndLongSoundsAreSplit() {
        Speaker speaker = new Speaker(ParamsJson.of(SpeakerParams.class, "{\"volumeDb\": 6.0, \"maxChunkMs\": 100}"));
        MethodHarness h = MethodHarness.started("speaker", speaker);
        h.push("audio", stereo(4000, 0.2, 0.1));
        assertThat(h.values("speaker")).hasSize(3);
        for (Payload p : h.values("speaker")) {
            AudioChunk c = (AudioChunk) p;
            assertThat(c.format()).isEqualTo(AudioFormat.MONO_16K);
            assertThat(c.frameCount()).isLessThanOrEqualTo(1600);
        }
        double v = ((AudioChunk) h.last("speaker")).channel(0)[10];
        assertThat(v).isCloseTo(0.15 * Math.pow(10, 6.0 / 20), within(1e-3));
        h.push("audio", stereo(10, 0.9, 0.9));
        assertThat(speaker.clipped()).isEqualTo(10);
        assertThat(((AudioChunk) h.last("speaker")).channel(0)[0]).isCloseTo(1.0, within(1e-3));
    }

    @Test
    void textBecomesATone() {
        MethodHarness h = MethodHarness.started("speaker", new Speaker(SpeakerParams.defaults()));
        h.push("text", new TextValue("1000:200"));
        AudioChunk c = (AudioChunk) h.last("speaker");
        double[] x = c.channel(0);
        assertThat(x).hasSize(3200);
        int crossings = 0;
        for (int i = 1; i < x.length; i++) {
            if (x[i - 1] < 0 && x[i] >= 0) {
                crossings++;
            }
        }
        assertThat(crossings).isBetween(198, 201);
    }
}
