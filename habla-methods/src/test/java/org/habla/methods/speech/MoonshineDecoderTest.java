package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.habla.methods.audio.MonoAudio;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;

@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class MoonshineDecoderTest {

    private MoonshineDecoder decoder;

    private MoonshineDecoder decoder() throws IOException {
        if (decoder == null) {
            decoder = MoonshineDecoder.load(SphinxDecoder.bundledGrammar(), MoonshineModelFolder.required(), 1,
                    SpeechRecognitionParams.defaults().moonshineStepBonus());
        }
        return decoder;
    }

    @AfterAll
    void close() {
        if (decoder != null) {
            decoder.close();
        }
    }

    @Test
    void theSimulatorsTeachersAreHeardAsTheirPhrasesWithConfidence() throws IOException {
        List<Utterances.Utterance> all = Utterances.all();
        List<String> misses = new ArrayList<>();
        int right = 0;
        int tried = 0;
        // every third recording: both voices, every phrase, in a few seconds
        for (int i = 0; i < all.size(); i += 3) {
            Utterances.Utterance u = all.get(i);
            double[] mono = MonoAudio.resample(u.audio().channel(0), u.audio().format().sampleRateHz(), 16_000);
            Optional<SpeechEngine.Decoded> d = decoder().decode(MonoAudio.chunk(UtteranceTrim.trim(mono, 16_000), 16_000));
            tried++;
            if (d.isPresent() && d.get().phrase().equals(u.phrase())
                    && d.get().confidence() >= SpeechRecognitionParams.defaults().moonshineMinConfidence()) {
                right++;
            } else {
                misses.add(u.file() + " -> " + d.map(x -> x.phrase() + " " + x.confidence()).orElse("nothing"));
            }
        }
        System.out.printf("moonshine: %d of %d recordings of the simulator's voices heard; misses %s%n", right, tried,
                misses);
        assertThat(right).as("recordings heard as their phrase, misses " + misses).isGreaterThanOrEqualTo(tried - 1);
    }

    @Test
    void whatIsSaidIsAlwaysAPhraseOfTheGrammarEvenForNoise() throws IOException {
        double[] noise = new double[16_000];
        java.util.Random r = new java.util.Random(3);
        for (int i = 0; i < noise.length; i++) {
            noise[i] = r.nextGaussian() * 0.1;
        }
        Optional<SpeechEngine.Decoded> d = decoder().decode(MonoAudio.chunk(noise, 16_000));
        assertThat(d).isPresent();
        assertThat(decoder().phrases()).contains(d.get().phrase());
        assertThat(d.get().confidence()).as("noise heard as " + d.get().phrase())
                .isLessThan(SpeechRecognitionParams.defaults().moonshineMinConfidence());
    }

    @Test
    void theStepBonusLetsALongerPhraseWinOverAOneWordPhraseOnlyWhenItIsCloseEnough() {
        MoonshineModel.RowScore no = new MoonshineModel.RowScore(-3, 0, 2, -2);
        MoonshineModel.RowScore goBack = new MoonshineModel.RowScore(-8, 0, 3, -5);
        MoonshineModel.RowScore[] scores = {no, goBack};
        assertThat(MoonshineDecoder.best(scores, 0)).as("without a bonus the likelier phrase").isZero();
        assertThat(MoonshineDecoder.best(scores, 8)).as("8 per step: -3 + 16 < -8 + 24").isOne();
        assertThat(MoonshineDecoder.best(scores, 4)).as("4 per step: -3 + 8 > -8 + 12").isZero();
    }

    @Test
    void aModelFolderWithoutTheModelIsRefusedNamingTheCommandThatFetchesIt() throws IOException {
        Path empty = Files.createTempDirectory("habla-no-model");
        assertThatThrownBy(() -> MoonshineDecoder.load(SphinxDecoder.bundledGrammar(), empty, 1, 0))
                .hasMessageContaining(MoonshineFiles.FETCH).hasMessageContaining("encoder.onnx");
        assertThatThrownBy(() -> SpeechRecognitionParams.defaults().withEngine("moonshine").withModel(empty.toString()))
                .hasMessageContaining(MoonshineFiles.FETCH);
        Files.delete(empty);
    }

    @Test
    void aModelFileThatDiffersFromItsPinnedSumIsRefused() throws IOException {
        Path copy = Files.createTempDirectory("habla-model-copy");
        for (String f : MoonshineFiles.pinned().keySet()) {
            Files.createSymbolicLink(copy.resolve(f), MoonshineModelFolder.required().resolve(f));
        }
        Files.delete(copy.resolve("tokenizer.json"));
        Files.writeString(copy.resolve("tokenizer.json"), "{}");
        assertThatThrownBy(() -> MoonshineFiles.verify(copy)).hasMessageContaining("tokenizer.json")
                .hasMessageContaining("not the pinned file");
        for (String f : MoonshineFiles.pinned().keySet()) {
            Files.delete(copy.resolve(f));
        }
        Files.delete(copy);
    }
}
