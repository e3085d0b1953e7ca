package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The speech chains of config/aibo.json (Moonshine) and config/aibo-sphinx4.json on the small part of the
 * evaluation set kept in the sources: two voices never used for tuning (espeak-ng's Caribbean English,
 * clean; flite's ARCTIC slt, a recording-based voice, in pink noise at 10 dB SNR), each saying the nine
 * phrases and four words outside the grammar ("go", "good", "turn", "hello robot") into a stream that
 * audio-processing cuts. {@code bench/run speech} measures the whole held-out set.
 */
class HeldOutVoicesTest {

    static final Path SUBSET = Path.of("src/test/resources/speech-eval-subset");

    private static StreamScore score(String config) throws Exception {
        SpeechChain chain = SpeechChain.fromConfig(Path.of(config), "audio", "speech");
        StreamScore all = new StreamScore();
        for (EvalSet.Voice v : EvalSet.read(SUBSET)) {
            for (String condition : EvalSet.CONDITIONS) {
                if (v.has(condition)) {
                    List<SpeechChain.Heard> heard = chain.run(Utterances.readWav(v.stream(condition)), 32);
                    StreamScore s = new StreamScore();
                    s.add(v.name() + " " + condition, v.items(), heard, EvalSet.GRAMMAR);
                    System.out.printf("speech-recognition (%s), held-out %s %s: %s%n", config, v.name(), condition, s);
                    all.add(s);
                }
            }
        }
        System.out.println("misses: " + all.misses);
        assertThat(all.inGrammar).isEqualTo(18);
        assertThat(all.outOfGrammar).isEqualTo(8);
        assertThat(all.notInGrammar).as("phrases outside the grammar").isZero();
        assertThat(all.falseAlarms).as("phrases said in the silence before the first word").isZero();
        return all;
    }

    @Test
    void voicesNeverTunedOnAreHeardThroughTheMoonshineChainAndNothingOutsideTheGrammarIsSaid() throws Exception {
        MoonshineModelFolder.required();
        StreamScore all = score("../config/aibo.json");
        assertThat(all.inGrammarRight).as("in-grammar phrases heard right").isGreaterThanOrEqualTo(MOONSHINE_MIN_RIGHT);
        assertThat(all.outOfGrammarRejected).as("out-of-grammar words that gave nothing")
                .isGreaterThanOrEqualTo(MOONSHINE_MIN_SILENT);
    }

    @Test
    void voicesNeverTunedOnAreHeardThroughTheSphinxChainAndNothingOutsideTheGrammarIsSaid() throws Exception {
        StreamScore all = score("../config/aibo-sphinx4.json");
        assertThat(all.inGrammarRight).as("in-grammar phrases heard right").isGreaterThanOrEqualTo(MIN_RIGHT);
        assertThat(all.outOfGrammarRejected).as("out-of-grammar words that gave nothing").isGreaterThanOrEqualTo(MIN_SILENT);
    }

    /**
     * What the Sphinx-4 chain reached (10 of 18 and 1 of 8 when this test was written; 11 and 5 with the
     * garbage words), less a margin: a regression shows.
     */
    static final int MIN_RIGHT = 9;
    static final int MIN_SILENT = 4;
    /**
     * What the Moonshine chain reached (11 of 18 and 7 of 8 when this test was written: most of its misses
     * are phrases in pink noise it heard too unsure to say), less a margin.
     */
    static final int MOONSHINE_MIN_RIGHT = 10;
    static final int MOONSHINE_MIN_SILENT = 6;
}
