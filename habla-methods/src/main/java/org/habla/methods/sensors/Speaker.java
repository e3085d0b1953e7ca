package org.habla.methods.sensors;

import java.util.List;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.voice.ToneSynth;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The general speaker method, type {@code speaker}: it plays sounds on the robot. Input {@code audio}
 * takes PCM in any format (e.g. from the {@code speech} method); input {@code text} takes a text and
 * plays it as tones ({@link ToneSynth}: {@code "880:200"} is a 200 ms beep at 880 Hz, words become
 * chirps and melodies). Output {@code speaker}, listed under the config's {@code commands}, sends mono
 * 16-bit PCM with the {@code volumeDb} gain, in chunks of at most {@code maxChunkMs}, so one long
 * sound never becomes one oversized packet. Either input may be left unwired.
 */
public final class Speaker extends SensorActuatorMethod {

    private static final OutputPort<AudioChunk> SPEAKER = OutputPort.of("speaker", AudioChunk.class,
            new Shape(PayloadKind.AUDIO, "", List.of(), "mono 16-bit PCM to play"));
    private static final InputPort<TextValue> TEXT = InputPort.optional("text", TextValue.class, Delivery.queue(16));

    private final SpeakerParams params;
    private final double gain;
    private final Output<AudioChunk> speaker = output(SPEAKER);
    private long clipped;

    Speaker(SpeakerParams params) {
        this.params = params;
        this.gain = Math.pow(10, params.volumeDb() / 20);
        input(audioIn(params.queue()), this::onAudio);
        input(TEXT, this::onText);
    }

    /** The ports of a speaker with these params: the audio input queues {@code queue} chunks. */
    static Ports ports(SpeakerParams params) {
        return Ports.of(SPEAKER, audioIn(params.queue()), TEXT);
    }

    private static InputPort<AudioChunk> audioIn(int queue) {
        return InputPort.optional("audio", AudioChunk.class, Delivery.queue(queue));
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        int channels = chunk.format().channels();
        double[] mono = new double[chunk.frameCount()];
        for (int c = 0; c < channels; c++) {
            double[] ch = chunk.channel(c);
            for (int i = 0; i < mono.length; i++) {
                mono[i] += ch[i] * gain / channels;
            }
        }
        for (int i = 0; i < mono.length; i++) {
            if (Math.abs(mono[i]) > 1) {
                clipped++;
                mono[i] = Math.copySign(1, mono[i]);
            }
        }
        play(mono, chunk.format().sampleRateHz());
    }

    private void onText(TextValue text, Sample sample) {
        String t = text.text().length() > 500 ? text.text().substring(0, 500) : text.text();
        double[] tones = ToneSynth.render(ToneSynth.tones(t, 60), params.sampleRateHz(), params.amplitude());
        for (int i = 0; i < tones.length; i++) {
            tones[i] = Math.max(-1, Math.min(1, tones[i] * gain));
        }
        play(tones, params.sampleRateHz());
    }

    private void play(double[] mono, int rateHz) {
        ToneSynth.chunks(mono, rateHz, params.maxChunkMs()).forEach(c -> emit(speaker, c));
    }

    /** Samples clipped at full scale by the gain, since start. */
    public long clipped() {
        return clipped;
    }

    /** Makes {@code speaker} methods. */
    public static final class Provider extends SimpleMethodProvider<SpeakerParams> {
        public Provider() {
            super("speaker", "Plays audio or text-made tones on the robot's speaker as mono 16-bit chunks",
                    SpeakerParams.class, Speaker::ports, (layer, p) -> new Speaker(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
