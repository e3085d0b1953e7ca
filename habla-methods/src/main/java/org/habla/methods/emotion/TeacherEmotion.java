package org.habla.methods.emotion;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The {@code emotion} record of {@code emotion-recognition}: the teacher's attitude at a word, a touch or a reward.
 *
 * <pre>{@code {"emotion": "happy", "valence": 0.6, "arousal": 0.4, "words": "good dog", "intensity": -18.0,
 *   "source": "words"}}</pre>
 */
public record TeacherEmotion(String emotion, double valence, double arousal, String words, double intensity,
        String source) implements RecordForm {

    /** The fields of an emotion record. */
    public static final RecordLayout<TeacherEmotion> LAYOUT = RecordLayout.of(TeacherEmotion.class)
            .text("emotion", TeacherEmotion::emotion).doc("the emotion named: happy, excited, angry, sad or neutral")
            .number("valence", TeacherEmotion::valence).doc("-1 (displeasure) .. 1 (pleasure)")
            .number("arousal", TeacherEmotion::arousal).doc("how stirred the teacher is; about 0.5 for an ordinary voice")
            .text("words", TeacherEmotion::words).doc("the words it came from, empty for a touch or reward")
            .number("intensity", TeacherEmotion::intensity).unit("dB").doc("the utterance's level; -120 with no audio")
            .text("source", TeacherEmotion::source).doc("what it came from: words, touch or reward")
            .build();

    @Override
    public RecordLayout<TeacherEmotion> layout() {
        return LAYOUT;
    }

    /** The emotion a record names (the form's inside the daemon, else its JSON's), empty when it names none. */
    public static String emotionOf(RecordValue record) {
        return record.as(TeacherEmotion.class, r -> new TeacherEmotion(r.get("emotion").asText(""), Double.NaN,
                Double.NaN, "", Double.NaN, "")).emotion();
    }
}
