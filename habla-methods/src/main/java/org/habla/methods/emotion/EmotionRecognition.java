package org.habla.methods.emotion;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.methods.audio.FrameFeatures;
import org.habla.plugin.SimpleMethodProvider;
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
 *       last {@code utteranceWindowMs} are compared with a running baseline of the speaker (the
 *       first utterance sets it; each one then moves it by {@code baselineWeight}; with
 *       {@code voices} above 1, an utterance more than {@code voiceSplitOctaves} in pitch from every
 *       baseline starts a baseline of its own, so two teachers are each measured against themselves): loud = (level − baseline) / loudRangeDb
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

    private static final InputPort<TextValue> WORDS = InputPort.optional("words", TextValue.class, Delivery.queue(16));
    private static final InputPort<RecordValue> FEATURES = InputPort.optional("features", RecordValue.class,
            Delivery.queue(1024));
    private static final InputPort<TextValue> TOUCH = InputPort.optional("touch", TextValue.class, Delivery.queue(16));
    private static final InputPort<NumberValue> REWARD = InputPort.optional("reward", NumberValue.class,
            Delivery.queue(16));
    private static final OutputPort<RecordValue> EMOTION = OutputPort.of("emotion", RecordValue.class,
            Shape.record("the teacher's attitude at each word, touch or reward", TeacherEmotion.LAYOUT));
    static final Ports PORTS = Ports.of(WORDS, FEATURES, TOUCH, REWARD, EMOTION);

    private record Frame(long micros, double db, double pitchHz, boolean voiced) {
    }

    private final EmotionRecognitionParams params;
    private final List<String> phrases;
    private final Output<RecordValue> emotion = output(EMOTION);
    private final ArrayDeque<Frame> frames = new ArrayDeque<>();
    /** A speaker's usual level and pitch, moved by each of their utterances. */
    private static final class Baseline {
        double db;
        double pitchHz;

        Baseline(double db, double pitchHz) {
            this.db = db;
            this.pitchHz = pitchHz;
        }

        double octavesTo(double hz) {
            return Math.abs(Math.log(hz / pitchHz) / Math.log(2));
        }
    }

    private final List<Baseline> baselines = new ArrayList<>();
    private long lastWordsMicros = Long.MIN_VALUE;
    private long ignored;

    EmotionRecognition(EmotionRecognitionParams params) {
        this.params = params;
        this.phrases = new ArrayList<>(params.valence().keySet());
        phrases.sort(Comparator.comparingInt((String p) -> p.split(" ").length).reversed().thenComparing(p -> p));
        input(WORDS, this::onWords);
        input(FEATURES, this::onFeatures);
        input(TOUCH, this::onTouch);
        input(REWARD, this::onReward);
    }

    private void onFeatures(RecordValue f, Sample sample) {
        FrameFeatures features = FrameFeatures.fromRecord(f);
        if (!Double.isFinite(features.db())) {
            ignored++;
            return;
        }
        double hz = Double.isFinite(features.pitchHz()) ? features.pitchHz() : 0;
        boolean voiced = features.voiced() && hz > 0;
        frames.addLast(new Frame(sample.sourceMicros(), features.db(), hz, voiced));
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
            Baseline base = baselineFor(db, pitch);
            loud = clamp((db - base.db) / params.loudRangeDb(), -1, 1);
            high = clamp(Math.log(pitch / base.pitchHz) / Math.log(2) / params.pitchRangeOctaves(), -1, 1);
            base.db += params.baselineWeight() * (db - base.db);
            base.pitchHz *= Math.exp(params.baselineWeight() * Math.log(pitch / base.pitchHz));
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

    /**
     * The baseline of the speaker an utterance sounds like: the one nearest in pitch, or a new one (set
     * to the utterance) when every one is more than {@code voiceSplitOctaves} away and there are fewer
     * than {@code voices}.
     */
    private Baseline baselineFor(double db, double pitchHz) {
        Baseline nearest = null;
        for (Baseline b : baselines) {
            if (nearest == null || b.octavesTo(pitchHz) < nearest.octavesTo(pitchHz)) {
                nearest = b;
            }
        }
        if (nearest == null || (nearest.octavesTo(pitchHz) > params.voiceSplitOctaves() && baselines.size() < params.voices())) {
            nearest = new Baseline(db, pitchHz);
            baselines.add(nearest);
        }
        return nearest;
    }

    private double currentDb() {
        return frames.isEmpty() ? SILENCE_DB : frames.peekLast().db();
    }

    private void report(double valence, double arousal, String words, double intensityDb, String source) {
        emit(emotion, RecordValue.of(new TeacherEmotion(classify(valence, arousal), valence, arousal, words, intensityDb,
                source)));
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

    /** The running baseline level of the first voice heard, or null before the first utterance. */
    public Double baselineDb() {
        return baselines.isEmpty() ? null : baselines.get(0).db;
    }

    /** How many voices have a baseline so far. */
    public int voicesHeard() {
        return baselines.size();
    }

    /** Makes {@code emotion-recognition} methods. */
    public static final class Provider extends SimpleMethodProvider<EmotionRecognitionParams> {
        public Provider() {
            super("emotion-recognition",
                    "Names the teacher's emotion from the words, the voice's loudness and pitch, touches and rewards",
                    EmotionRecognitionParams.class, PORTS, (layer, p) -> new EmotionRecognition(p), Layer.VIRTUAL);
        }
    }
}
