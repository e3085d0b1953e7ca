package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.habla.method.MethodHarness;
import org.habla.methods.audio.MonoAudio;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

/** {@code speech-recognition} with the moonshine engine, through the method's own inputs and outputs. */
class MoonshineRecognitionTest {

    @Test
    void aPhraseIsSaidWithItsEngineAndTheStatusLineCountsWhatWasHeard() throws Exception {
        MoonshineModelFolder.required();
        MethodHarness h = MethodHarness.started("speech",
                new SpeechRecognition(SpeechRecognitionParams.defaults().withEngine("moonshine")));
        assertThat(h.readinessDetail()).isEqualTo("loading the moonshine model");
        assertThat(h.runBackground()).isEqualTo(1);
        h.runBackgroundAtOnce();
        assertThat(h.ready()).isTrue();
        assertThat(h.readinessDetail()).startsWith("moonshine: 0 utterances cut");

        Utterances.Utterance u = Utterances.all().get(0);
        h.push("segments", u.audio());
        assertThat(h.values("words")).containsExactly(new TextValue(u.phrase()));
        RecordValue r = (RecordValue) h.last("result");
        assertThat(r.text("engine")).isEqualTo("moonshine");
        assertThat(r.number("confidence")).isBetween(SpeechRecognitionParams.defaults().moonshineMinConfidence(), 1.0);

        double[] hiss = new double[16_000];
        Random random = new Random(5);
        for (int i = 0; i < hiss.length; i++) {
            hiss[i] = random.nextGaussian() * 0.05;
        }
        h.clear().push("segments", MonoAudio.chunk(hiss, 16_000));
        assertThat(h.values("words")).isEqualTo(List.of());
        assertThat(h.readinessDetail()).startsWith("moonshine: 2 utterances cut, 1 decoded, 1 said; rejected: 1 without "
                + "voice, 0 no phrase, 0 low confidence; no utterance open; 0 queued; dropped: 0 over maxPending, 0 waited over 5 s; "
                + "decoding p50 ");
        h.stop();
    }
}
