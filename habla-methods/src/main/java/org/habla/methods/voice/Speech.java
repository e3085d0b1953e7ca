package org.habla.methods.voice;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.methods.emotion.TeacherEmotion;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The speech method, type {@code speech}: it gives the robot a voice to show emotion with. Input
 * {@code text} (typically the control architecture's {@code say} socket) is said through
 * {@link ToneSynth}: a melody for each emotion word, a chirp for each other word. Optional input
 * {@code emotion} (the record of {@code emotion-recognition}) makes the robot say the emotion when
 * it changes to one of {@code sayEmotions}, at most once per {@code emotionIntervalMs}. Output {@code audio} is mono 16-bit PCM in
 * chunks of at most {@code chunkMs}, to be carried down to a {@code speaker} method. The same text
 * always sounds the same.
 */
public final class Speech extends VirtualMethod {

    private static final OutputPort<AudioChunk> AUDIO = OutputPort.of("audio", AudioChunk.class,
            new Shape(PayloadKind.AUDIO, "", java.util.List.of(), "the voice, mono 16-bit PCM"));
    private static final InputPort<TextValue> TEXT = InputPort.of("text", TextValue.class, Delivery.queue(16));
    private static final InputPort<RecordValue> EMOTION = InputPort.optional("emotion", RecordValue.class,
            Delivery.latest());
    static final Ports PORTS = Ports.of(AUDIO, TEXT, EMOTION);

    private final SpeechParams params;
    private final Output<AudioChunk> audio = output(AUDIO);
    private String lastEmotion = "";
    private long lastEmotionMicros = Long.MIN_VALUE;

    Speech(SpeechParams params) {
        this.params = params;
        input(TEXT, this::onText);
        input(EMOTION, this::onEmotion);
    }

    private void onText(TextValue text, Sample sample) {
        String t = text.text();
        say(t.length() > params.maxChars() ? t.substring(0, params.maxChars()) : t);
    }

    private void onEmotion(RecordValue record, Sample sample) {
        String e = TeacherEmotion.emotionOf(record);
        long now = nowMicros();
        if (!params.sayEmotions().contains(e)) {
            lastEmotion = e;
            return;
        }
        if (!params.speakEmotions() || e.equals(lastEmotion)
                || (lastEmotionMicros != Long.MIN_VALUE && now - lastEmotionMicros < params.emotionIntervalMs() * 1000L)) {
            return;
        }
        lastEmotion = e;
        lastEmotionMicros = now;
        say(e);
    }

    private void say(String text) {
        double[] samples = ToneSynth.render(ToneSynth.tones(text, params.wordGapMs()), params.sampleRateHz(),
                params.amplitude());
        ToneSynth.chunks(samples, params.sampleRateHz(), params.chunkMs()).forEach(c -> emit(audio, c));
    }

    /** Makes {@code speech} methods. */
    public static final class Provider extends SimpleMethodProvider<SpeechParams> {
        public Provider() {
            super("speech", "Says a text or an emotion as short tone melodies for a speaker",
                    SpeechParams.class, PORTS, (layer, p) -> new Speech(p), Layer.VIRTUAL);
        }
    }
}
