package org.habla.methods.audio;

import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The general sound analysis of the processing layer, type {@code audio-processing}. Input
 * {@code audio} takes chunks of any rate, mono or multi-channel (mixed to mono). The signal is cut
 * into frames of {@code frameMs}; for each the method emits on {@code features} an
 * {@code audio-features} record ({@code rms}, {@code db}, {@code pitchHz}, {@code voiced},
 * {@code spectrum}) — what an emotion recogniser needs about intonation and volume. On
 * {@code segments} it emits each utterance its voice-activity detector finds ({@link UtteranceGate}),
 * as one mono 16-bit chunk at the input's rate, for the recognisers to work on whole utterances.
 */
public final class AudioProcessing extends ProcessingMethod {

    /** The lowest sample rate analysed: below it there is no room for a voice's pitch and spectrum. */
    static final int MIN_RATE_HZ = 4000;

    private static final OutputPort<RecordValue> FEATURES = OutputPort.of("features", RecordValue.class,
            Shape.record("level, pitch and band spectrum of one frame", FrameFeatures.LAYOUT));
    private static final OutputPort<AudioChunk> SEGMENTS = OutputPort.of("segments", AudioChunk.class,
            new Shape(PayloadKind.AUDIO, "", java.util.List.of(), "one utterance or tone, mono 16-bit"));

    private final AudioProcessingParams params;
    private final Output<RecordValue> features = output(FEATURES);
    private final Output<AudioChunk> segments = output(SEGMENTS);

    private AudioFormat format;
    private FrameAnalyzer analyzer;
    private UtteranceGate gate;
    private double[] pending = new double[0];
    private int pendingCount;

    AudioProcessing(AudioProcessingParams params) {
        this.params = params;
        input(audio(params), this::onAudio);
    }

    /** The ports of an audio processing whose input queue holds {@code queue} chunks. */
    static Ports ports(AudioProcessingParams params) {
        return Ports.of(audio(params), FEATURES, SEGMENTS);
    }

    private static InputPort<AudioChunk> audio(AudioProcessingParams params) {
        return InputPort.of("audio", AudioChunk.class, Delivery.queue(params.queue()));
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        if (!chunk.format().equals(format)) {
            restart(chunk.format());
        }
        if (analyzer == null) {
            return;
        }
        double[] mono = MonoAudio.mix(chunk);
        gate.offer(mono).forEach(this::emitSegment);
        int frame = analyzer.frameLength();
        int at = 0;
        while (at < mono.length) {
            int take = Math.min(frame - pendingCount, mono.length - at);
            System.arraycopy(mono, at, pending, pendingCount, take);
            pendingCount += take;
            at += take;
            if (pendingCount == frame) {
                double[] full = pending;
                pending = new double[frame];
                pendingCount = 0;
                analyze(full);
            }
        }
    }

    private void analyze(double[] frame) {
        FrameFeatures f = analyzer.analyze(frame);
        emit(features, f.toRecord());
    }

    private void restart(AudioFormat next) {
        if (gate != null) {
            gate.flush().ifPresent(this::emitSegment);
        }
        format = next;
        analyzer = null;
        gate = null;
        int rate = next.sampleRateHz();
        if (rate < MIN_RATE_HZ) {
            log().warn("{}: audio at {} Hz is below the {} Hz this method analyses; ignoring it", id(), rate,
                    MIN_RATE_HZ);
            return;
        }
        int frame = Math.max(16, (int) Math.round(params.frameMs() * rate / 1000));
        double minPitch = Math.max(params.minPitchHz(), 2.0 * rate / frame);
        double maxPitch = Math.min(params.maxPitchHz(), rate / 2.0 - 1);
        if (!(maxPitch > minPitch)) {
            log().warn("{}: no pitch range fits {} with {} ms frames; ignoring this audio", id(), next,
                    params.frameMs());
            return;
        }
        analyzer = new FrameAnalyzer(rate, frame, params.bands(), minPitch, maxPitch, params.aperiodicity(),
                params.voicedMinDb());
        gate = new UtteranceGate(rate, params.gate());
        pending = new double[frame];
        pendingCount = 0;
    }

    private void emitSegment(double[] samples) {
        emit(segments, MonoAudio.chunk(samples, format.sampleRateHz()));
    }

    /** The utterance gate's noise floor in dB, or empty before the first frame. */
    public Optional<Double> noiseFloorDb() {
        return gate == null ? Optional.empty() : Optional.of(gate.floorDb());
    }

    /** Makes {@code audio-processing} methods. */
    public static final class Provider extends SimpleMethodProvider<AudioProcessingParams> {
        public Provider() {
            super("audio-processing", "Per-frame level, pitch and spectrum of audio, and the utterances cut out of it",
                    AudioProcessingParams.class, AudioProcessing::ports, (layer, p) -> new AudioProcessing(p),
                    Layer.PROCESSING);
        }
    }
}
