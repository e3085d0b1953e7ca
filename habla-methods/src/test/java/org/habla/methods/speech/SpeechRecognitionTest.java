package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.methods.audio.MonoAudio;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SpeechRecognitionTest {

    /** Starts the method and loads its model (the background task the engine would run). */
    private static MethodHarness loaded(SpeechRecognitionParams params) {
        MethodHarness h = MethodHarness.started("speech", new SpeechRecognition(params));
        assertThat(h.ready()).isFalse();
        assertThat(h.readinessDetail()).isEqualTo("loading model");
        long t0 = System.nanoTime();
        assertThat(h.runBackground()).isEqualTo(1);
        System.out.printf("speech-recognition: model loaded in %d ms%n", (System.nanoTime() - t0) / 1_000_000);
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);
        assertThat(h.ready()).isTrue();
        return h.runBackgroundAtOnce();
    }

    @Test
    void recognisesAtLeast95PercentOfTheRecordedUtterancesOfBothVoices() throws Exception {
        MethodHarness h = loaded(SpeechRecognitionParams.defaults());
        List<Utterances.Utterance> all = Utterances.all();
        assertThat(all).hasSizeGreaterThanOrEqualTo(72);
        Map<String, int[]> perVoice = new LinkedHashMap<>();
        List<String> misses = new ArrayList<>();
        long totalMs = 0;
        long maxMs = 0;
        for (Utterances.Utterance u : all) {
            h.clear();
            h.push("segments", u.audio());
            List<Payload> heard = h.values("words");
            int[] tally = perVoice.computeIfAbsent(u.voice(), v -> new int[2]);
            tally[1]++;
            if (heard.equals(List.of(new TextValue(u.phrase())))) {
                tally[0]++;
            } else {
                misses.add(u.file() + " -> " + heard);
            }
            if (!heard.isEmpty()) {
                RecordValue r = (RecordValue) h.last("result");
                assertThat(r.text("phrase")).isEqualTo(((TextValue) heard.get(0)).text());
                assertThat(r.number("audioMs")).isCloseTo(u.audio().frameCount() / 16.0, org.assertj.core.api.Assertions.within(1.0));
                totalMs += (long) r.number("timeMs");
                maxMs = Math.max(maxMs, (long) r.number("timeMs"));
            }
        }
        int correct = perVoice.values().stream().mapToInt(t -> t[0]).sum();
        double accuracy = 100.0 * correct / all.size();
        perVoice.forEach((voice, t) -> System.out.printf("speech-recognition: %s %d of %d correct%n", voice, t[0], t[1]));
        System.out.printf("speech-recognition: %d of %d utterances correct (%.1f%%), %.0f ms per utterance on average, "
                + "%d ms at most; misses %s%n", correct, all.size(), accuracy, totalMs / (double) all.size(), maxMs, misses);
        assertThat(perVoice).hasSizeGreaterThanOrEqualTo(2);
        assertThat(accuracy).isGreaterThanOrEqualTo(95);
    }

    @Test
    void cutsUtterancesOutOfAStreamAndListensOnlyForItsOwnGrammar(@TempDir Path dir) throws Exception {
        Path grammar = dir.resolve("turns.gram");
        Files.writeString(grammar, "#JSGF V1.0;\ngrammar turns;\npublic <turn> = turn left | turn right | stop;\n");
        MethodHarness h = loaded(new SpeechRecognitionParams(grammar.toString(), 8, null, null, null, null));
        List<Utterances.Utterance> all = Utterances.all();
        List<String> said = List.of("turn left", "stop", "turn right", "turn left");
        Random r = new Random(4);
        int rate = 22_050;
        List<double[]> parts = new ArrayList<>();
        parts.add(noise(r, (int) (0.8 * rate)));
        for (int i = 0; i < said.size(); i++) {
            String phrase = said.get(i);
            Utterances.Utterance u = all.stream().filter(x -> x.phrase().equals(phrase)).skip(i % 2 == 0 ? 1 : 5)
                    .findFirst().orElseThrow();
            double[] speech = MonoAudio.resample(u.audio().channel(0), 16_000, rate);
            double[] n = noise(r, speech.length);
            for (int k = 0; k < speech.length; k++) {
                speech[k] += n[k];
            }
            parts.add(speech);
            parts.add(noise(r, rate));
        }
        AudioFormat stereo = new AudioFormat(rate, 2, 16);
        int chunk = rate / 50;
        for (double[] part : parts) {
            for (int start = 0; start < part.length; start += chunk) {
                int end = Math.min(part.length, start + chunk);
                byte[] pcm = new byte[(end - start) * 4];
                for (int k = start; k < end; k++) {
                    short s = (short) Math.max(-32768, Math.min(32767, Math.round(part[k] * 32768)));
                    int at = (k - start) * 4;
                    pcm[at] = (byte) s;
                    pcm[at + 1] = (byte) (s >> 8);
                    pcm[at + 2] = (byte) s;
                    pcm[at + 3] = (byte) (s >> 8);
                }
                h.push("audio", AudioChunk.wrap(stereo, pcm));
            }
        }
        System.out.printf("speech-recognition: from a 22.05 kHz stereo stream heard %s%n", h.values("words"));
        assertThat(h.values("words")).containsExactlyElementsOf(said.stream().map(TextValue::new).toList());
    }

    @Test
    void utterancesArrivingWhileTheModelLoadsWaitUpToMaxPending() throws Exception {
        MethodHarness h = MethodHarness.started("speech",
                new SpeechRecognition(new SpeechRecognitionParams(null, 2, null, null, null, null)));
        List<Utterances.Utterance> all = Utterances.all();
        List<String> phrases = List.of("go forward", "go back", "well done", "no");
        for (String phrase : phrases) {
            h.push("segments", all.stream().filter(u -> u.phrase().equals(phrase)).findFirst().orElseThrow().audio());
        }
        assertThat(h.values("words")).isEmpty();
        h.runBackgroundAtOnce();
        assertThat(h.values("words")).containsExactly(new TextValue("well done"), new TextValue("no"));
    }

    @Test
    void aMissingGrammarFileFailsTheMethodWithItsPath() {
        MethodHarness h = MethodHarness.started("speech",
                new SpeechRecognition(new SpeechRecognitionParams("/nonexistent/words.gram", null, null, null, null, null)));
        h.runBackground();
        assertThat(h.state()).isEqualTo(MethodState.FAILED);
        assertThatThrownBy(() -> new SpeechRecognitionParams("words.txt", null, null, null, null, null))
                .hasMessageContaining(".gram");
    }

    private static double[] noise(Random r, int samples) {
        double[] x = new double[samples];
        for (int i = 0; i < x.length; i++) {
            x[i] = r.nextGaussian() * 0.002;
        }
        return x;
    }
}
