package org.habla.methods.emotion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Map;
import java.util.Random;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class EmotionRecognitionTest {

    private final Random random = new Random(7);

    /** Pushes 10 ms feature frames: 0.3 s of background, then a voiced utterance, then the recognised words. */
    private RecordValue say(MethodHarness h, String words, double db, double pitchHz) {
        for (int i = 0; i < 30; i++) {
            h.advanceMillis(10);
            h.push("features", RecordValue.builder().put("rms", 0.001).put("db", -60 + random.nextGaussian())
                    .put("pitchHz", 0.0).put("voiced", false).build(), h.nowMicros());
        }
        for (int i = 0; i < 60; i++) {
            h.advanceMillis(10);
            double level = db + random.nextGaussian() * 1.5;
            double pitch = pitchHz * (1 + 0.03 * Math.sin(i / 5.0));
            h.push("features", RecordValue.builder().put("rms", Math.pow(10, level / 20)).put("db", level)
                    .put("pitchHz", pitch).put("voiced", true).build(), h.nowMicros());
        }
        h.advanceMillis(400);
        h.push("words", new TextValue(words), h.nowMicros());
        return (RecordValue) h.last("emotion");
    }

    @Test
    void wordsAndTheVoiceAgainstItsBaselineGiveTheFiveEmotions() {
        MethodHarness h = MethodHarness.started("emotion", new EmotionRecognition(EmotionRecognitionParams.defaults()));
        RecordValue first = say(h, "go forward", -30, 150);
        assertThat(first.text("emotion")).isEqualTo("neutral");
        assertThat(first.number("arousal")).isCloseTo(0.5, within(1e-9));
        assertThat(first.number("intensity")).isCloseTo(-30.0, within(1.0));

        RecordValue praise = say(h, "good dog", -30, 150);
        assertThat(praise.text("emotion")).isEqualTo("happy");
        assertThat(praise.number("valence")).isEqualTo(1.0);
        assertThat(praise.text("words")).isEqualTo("good dog");

        RecordValue cheer = say(h, "Well done!", -16, 230);
        assertThat(cheer.text("emotion")).isEqualTo("excited");
        assertThat(cheer.number("arousal")).isGreaterThan(0.8);

        RecordValue scold = say(h, "bad dog", -22, 150);
        assertThat(scold.text("emotion")).isEqualTo("angry");
        assertThat(scold.number("valence")).isEqualTo(-1.0);

        RecordValue sigh = say(h, "no", -42, 110);
        assertThat(sigh.text("emotion")).isEqualTo("sad");
        assertThat(sigh.number("arousal")).isLessThan(0.5);
        assertThat(sigh.text("source")).isEqualTo("words");
    }

    @Test
    void theBaselineFollowsTheVoiceSoTheSameLevelStopsCountingAsLoud() {
        EmotionRecognition m = new EmotionRecognition(EmotionRecognitionParams.defaults());
        MethodHarness h = MethodHarness.started("emotion", m);
        say(h, "go forward", -40, 150);
        double firstLoud = say(h, "turn left", -25, 150).number("arousal");
        double later = 0;
        for (int i = 0; i < 15; i++) {
            later = say(h, "turn left", -25, 150).number("arousal");
        }
        assertThat(firstLoud).isGreaterThan(0.75);
        assertThat(later).isLessThan(0.56);
        assertThat(m.baselineDb()).isCloseTo(-25, within(1.5));
    }

    @Test
    void twoVoicesEachGetTheirOwnBaselineSoOrdinaryCommandsStayCalm() {
        EmotionRecognitionParams two = ParamsJson.of(EmotionRecognitionParams.class, "{\"voices\": 2}");
        EmotionRecognition m = new EmotionRecognition(two);
        MethodHarness h = MethodHarness.started("emotion", m);
        MethodHarness one = MethodHarness.started("emotion", new EmotionRecognition(EmotionRecognitionParams.defaults()));
        double worstTwo = 0;
        double worstOne = 0;
        for (int i = 0; i < 8; i++) {
            double pitch = i % 2 == 0 ? 120 : 230;
            double db = i % 2 == 0 ? -22 : -26;
            worstTwo = Math.max(worstTwo, Math.abs(say(h, "turn left", db, pitch).number("arousal") - 0.5));
            worstOne = Math.max(worstOne, Math.abs(say(one, "turn left", db, pitch).number("arousal") - 0.5));
        }
        System.out.printf("emotion-recognition: arousal swing of ordinary commands from two voices: %.3f with one "
                + "baseline, %.3f with one per voice%n", worstOne, worstTwo);
        assertThat(m.voicesHeard()).isEqualTo(2);
        assertThat(worstOne).as("one baseline between two voices swings").isGreaterThan(0.1);
        assertThat(worstTwo).isLessThan(0.08);
        RecordValue cheer = say(h, "good dog", -12, 150);
        assertThat(cheer.text("emotion")).as("the low voice, loud and higher, is still excited").isEqualTo("excited");
    }

    @Test
    void phrasesMatchBeforeTheirWordsAndMixedWordsAverage() {
        EmotionRecognition m = new EmotionRecognition(EmotionRecognitionParams.defaults());
        MethodHarness.started("emotion", m);
        assertThat(m.wordValence("bad dog")).isEqualTo(-1.0);
        assertThat(m.wordValence("good boy, no")).isCloseTo((0.8 - 0.7) / 2, within(1e-9));
        assertThat(m.wordValence("goodness")).isEqualTo(0.0);
        assertThat(m.classify(0.1, 0.95)).isEqualTo("excited");
        assertThat(m.classify(0.1, 0.5)).isEqualTo("neutral");
    }

    @Test
    void touchesAndRewardsCarryTheirValenceAndOddInputsAreIgnored() {
        EmotionRecognitionParams p = ParamsJson.of(EmotionRecognitionParams.class, "{\"touchValence\": {\"backMiddle\": 1.0, \"headTouch\": -1.0}}");
        EmotionRecognition m = new EmotionRecognition(p);
        MethodHarness h = MethodHarness.started("emotion", m);
        h.push("touch", new TextValue("backMiddle"));
        assertThat(((RecordValue) h.last("emotion")).text("emotion")).isEqualTo("happy");
        h.push("touch", new TextValue("headTouch"));
        RecordValue pain = (RecordValue) h.last("emotion");
        assertThat(pain.text("emotion")).isEqualTo("angry");
        assertThat(pain.text("source")).isEqualTo("touch");
        assertThat(pain.number("intensity")).isEqualTo(-120.0);
        h.push("reward", new NumberValue(-0.5));
        assertThat(((RecordValue) h.last("emotion")).text("emotion")).isEqualTo("sad");
        h.push("reward", new NumberValue(3));
        assertThat(((RecordValue) h.last("emotion")).number("valence")).isEqualTo(1.0);
        h.push("touch", new TextValue("leftFrontPaw"));
        h.push("reward", new NumberValue(Double.NaN));
        h.push("features", RecordValue.builder().put("db", "loud").build());
        h.push("words", new TextValue("   "));
        assertThat(h.values("emotion")).hasSize(4);
        assertThat(m.ignored()).isEqualTo(3);
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);
    }
}
