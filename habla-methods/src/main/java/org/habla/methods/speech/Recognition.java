package org.habla.methods.speech;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code result} record of {@code speech-recognition}: the phrase recognised in one utterance, how sure the
 * recogniser is, and what it cost.
 *
 * <pre>{@code {"phrase": "go forward", "confidence": 0.912, "timeMs": 140, "audioMs": 1200, "score": -5123.4,
 *   "engine": "sphinx4"}}</pre>
 */
public record Recognition(String phrase, double confidence, long timeMs, long audioMs, double score, String engine)
        implements RecordForm {

    /** The fields of a result record. */
    public static final RecordLayout<Recognition> LAYOUT = RecordLayout.of(Recognition.class)
            .text("phrase", Recognition::phrase).doc("the phrase of the grammar recognised")
            .number("confidence", Recognition::confidence).doc("how sure the engine is, 0..1, to a thousandth")
            .longInteger("timeMs", Recognition::timeMs).unit("ms").doc("how long the decoding took")
            .longInteger("audioMs", Recognition::audioMs).unit("ms").doc("how long the utterance was")
            .number("score", Recognition::score).doc("the engine's own score of the phrase")
            .text("engine", Recognition::engine).doc("the engine that recognised it: sphinx4 or moonshine")
            .build();

    @Override
    public RecordLayout<Recognition> layout() {
        return LAYOUT;
    }
}
