package org.habla.methods.emotion;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.habla.method.Delivery;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.method.builtin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The emotion recognition method, type {@code emotion-recognition}: it tells the control architecture
 * the teacher's attitude, from what was said, how it was said, and touches and rewards. Output
 * {@code emotion} is the record
 * {@code {"emotion","valence","arousal","words","intensity","source"}}, one per event:
 *
 * <ul>
 *   <li><b>words</b> (input {@code words}, text from speech recognition): valence is the mean of the
 *       values of the listed words and phrases found in it (longest phrase first, whole words only;
 *       0 when none). The voice comes from input {@code features} (audio features per frame
 *       {@code {"rms","db","pitchHz","voiced"}}): the mean level and pitch of the voiced frames of the
 *       last {@code utteranceWindowMs} are compared with a running baseline (the first utterance sets
 *       it; each one then moves it by {@code baselineWeight}): loud = (level − baseline) / loudRangeDb
 *       and high = log2(pitch / baseline pitch) / pitchRangeOctaves, each within [−1, 1], and arousal
 *       = 0.5 + 0.3·loud + 0.2·high. Intensity is the utterance's level in dB.</li>
 *   <li><b>touch</b> (input {@code touch}, a button name): valence from {@code touchValence};
 *       arousal = 0.3 + 0.3·|valence|. Unlisted buttons are ignored.</li>
 *   <li><b>reward</b> (input {@code reward}, a number in [−1, 1]): valence is the reward;
 *       arousal = 0.3 + 0.3·|valence|.</li>
 * </ul>
 *
 * The emotion: valence ≥ positiveValence is {@code excited} when arousal ≥ excitedArousal, else
 * {@code happy}; valence ≤ −positiveValence is {@code angry} when arousal ≥ angryArousal, else
 * {@code sad}; in between {@code neutral}, unless arousal reaches 0.9 ({@code excited}: a shout).
 */
public final class EmotionRecognition extends VirtualMethod {

    /** The most audio frames kept for the utterance window. */
    private static final int MAX_FRAMES = 8192;
    /** The level reported when there is no audio to measure. */
    private static final double SILENCE_DB = -120;

    private record Frame(long micros, double db, double pitchHz, boolean voiced) {
    }

    private final EmotionRecognitionParams params;
    private final List<String> phrases;
    private final Output<RecordValue> emotion = output("emotion", RecordValue.class,
            Shape.record("the teacher's attitude at each word, touch or reward",
                    "emotion", "valence", "arousal", "words", "intensity", "source"));
    private final ArrayDeque<Frame> frames = new ArrayDeque<>();
    private Double baselineDb;
    private Double baselinePitchHz;
    private long lastWordsMicros = Long.MIN_VALUE;
    private long ignored;

    EmotionRecognition(EmotionRecognitionParams params) {
        this.params = params;
        this.phrases = new ArrayList<>(params.valence().keySet());
        phrases.sort(Comparator.comparingInt((String p) -> p.split(" ").length).reversed().thenComparing(p -> p));
        optionalInput("words", TextValue.class, Delivery.queue(16), this::onWords);
        optionalInput("features", RecordValue.class, Delivery.queue(1024), this::onFeatures);
        optionalInput("touch", TextValue.class, Delivery.queue(16), this::onTouch);
        optionalInput("reward", NumberValue.class, Delivery.queue(16), this::onReward);
    }

    private void onFeatures(RecordValue f, Sample sample) {
        JsonNode db = f.get("db");
        if (!db.isNumber() || !Double.isFinite(db.doubleValue())) {
            ignored++;
            return;
        }
        JsonNode pitch = f.get("pitchHz");
        double hz = pitch.isNumber() && Double.isFinite(pitch.doubleValue()) ? pitch.doubleValue() : 0;
        boolean voiced = f.get("voiced").asBoolean(false) && hz > 0;
        frames.addLast(new Frame(sample.sourceMicros(), db.doubleValue(), hz, voiced));
        long oldest = sample.sourceMicros() - params.utteranceWindowMs() * 1000L;
        while (frames.size() > MAX_FRAMES || (!frames.isEmpty() && frames.peekFirst().micros() < oldest)) {
            frames.removeFirst();
        }
    }

    private void onWords(TextValue words, Sample sample) {
        String text = words.text().trim().toLowerCase(Locale.ROOT).replaceAll("\\s+", " ");
        if (text.isEmpty()) {
            return;
        }
        long now = sample.sourceMicros();
        long from = Math.max(now - params.utteranceWindowMs() * 1000L, lastWordsMicros);
        lastWordsMicros = now;
        double sumDb = 0;
        double sumLogPitch = 0;
        int n = 0;
        for (Frame f : frames) {
            if (f.voiced() && f.micros() > from && f.micros() <= now) {
                sumDb += f.db();
                sumLogPitch += Math.log(f.pitchHz());
                n++;
            }
        }
        double valence = wordValence(text);
        double loud = 0;
        double high = 0;
        double intensity = frames.isEmpty() ? SILENCE_DB : frames.peekLast().db();
        if (n > 0) {
            double db = sumDb / n;
            double pitch = Math.exp(sumLogPitch / n);
            intensity = db;
            if (baselineDb == null) {
                baselineDb = db;
                baselinePitchHz = pitch;
            }
            loud = clamp((db - baselineDb) / params.loudRangeDb(), -1, 1);
            high = clamp(Math.log(pitch / baselinePitchHz) / Math.log(2) / params.pitchRangeOctaves(), -1, 1);
            baselineDb += params.baselineWeight() * (db - baselineDb);
            baselinePitchHz *= Math.exp(params.baselineWeight() * Math.log(pitch / baselinePitchHz));
        }
        double arousal = clamp(0.5 + 0.3 * loud + 0.2 * high, 0, 1);
        report(valence, arousal, text, intensity, "words");
    }

    private void onTouch(TextValue touch, Sample sample) {
        Double v = params.touchValence().get(touch.text().trim());
        if (v == null) {
            ignored++;
            return;
        }
        report(v, 0.3 + 0.3 * Math.abs(v), "", currentDb(), "touch");
    }

    private void onReward(NumberValue reward, Sample sample) {
        double r = reward.value();
        if (!Double.isFinite(r)) {
            ignored++;
            return;
        }
        double v = clamp(r, -1, 1);
        report(v, 0.3 + 0.3 * Math.abs(v), "", currentDb(), "reward");
    }

    /** The mean value of the listed phrases found in {@code text}, longest first, never overlapping. */
    double wordValence(String text) {
        String[] words = text.replaceAll("[^\\p{L}\\p{N}' ]", " ").trim().split("\\s+");
        boolean[] used = new boolean[words.length];
        double sum = 0;
        int found = 0;
        for (String phrase : phrases) {
            String[] p = phrase.split(" ");
            for (int i = 0; i + p.length <= words.length; i++) {
                boolean match = true;
                for (int k = 0; k < p.length && match; k++) {
                    match = !used[i + k] && words[i + k].equals(p[k]);
                }
                if (match) {
                    for (int k = 0; k < p.length; k++) {
                        used[i + k] = true;
                    }
                    sum += params.valence().get(phrase);
                    found++;
                }
            }
        }
        return found == 0 ? 0 : clamp(sum / found, -1, 1);
    }

    private double currentDb() {
        return frames.isEmpty() ? SILENCE_DB : frames.peekLast().db();
    }

    private void report(double valence, double arousal, String words, double intensityDb, String source) {
        emit(emotion, RecordValue.builder().put("emotion", classify(valence, arousal)).put("valence", valence)
                .put("arousal", arousal).put("words", words).put("intensity", intensityDb).put("source", source).build());
    }

    /** The rule that names the emotion of a valence and an arousal. */
    String classify(double valence, double arousal) {
        if (valence >= params.positiveValence()) {
            return arousal >= params.excitedArousal() ? "excited" : "happy";
        }
        if (valence <= -params.positiveValence()) {
            return arousal >= params.angryArousal() ? "angry" : "sad";
        }
        return arousal >= 0.9 ? "excited" : "neutral";
    }

    private static double clamp(double v, double min, double max) {
        return Math.max(min, Math.min(max, v));
    }

    /** Inputs that could not be used (bad features, unlisted touches, non-finite rewards), since start. */
    public long ignored() {
        return ignored;
    }

    /** The running baseline level, or null before the first utterance. */
    public Double baselineDb() {
        return baselineDb;
    }

    /** Makes {@code emotion-recognition} methods. */
    public static final class Provider extends SimpleMethodProvider<EmotionRecognitionParams> {
        public Provider() {
            super("emotion-recognition",
                    "Names the teacher's emotion from the words, the voice's loudness and pitch, touches and rewards",
                    EmotionRecognitionParams.class, (layer, p) -> new EmotionRecognition(p), Layer.VIRTUAL);
        }
    }
}
