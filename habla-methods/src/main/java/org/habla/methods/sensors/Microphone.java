package org.habla.methods.sensors;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * The general microphone method, type {@code microphone}: it stores the sound of an audio channel and
 * does the basic filtering the paper describes before handing it on. Each chunk of input {@code audio}
 * goes through a first-order high-pass filter (removing DC offset and rumble) and a noise gate whose
 * floor adapts: it falls at once to a quieter level and rises slowly, so steady background noise is
 * attenuated by {@code closedGainDb} while a sound {@code gateThresholdDb} above the floor passes
 * unchanged. Output {@code audio} is 16-bit PCM at the input's rate, mono when {@code downmix} is set.
 */
public final class Microphone extends SensorActuatorMethod {

    /** Time constant with which the floor follows a falling level. */
    private static final double FLOOR_FALL_MS = 50;
    private static final OutputPort<AudioChunk> AUDIO_OUT = OutputPort.of("audio", AudioChunk.class,
            new Shape(PayloadKind.AUDIO, "", java.util.List.of(), "filtered 16-bit PCM"));

    private final MicrophoneParams params;
    private final Output<AudioChunk> out = output(AUDIO_OUT);

    private AudioFormat lastFormat;
    private double[] hpPrevIn = new double[0];
    private double[] hpPrevOut = new double[0];
    private double floorRms;
    private double gain = 1;
    private double holdLeftMs;

    Microphone(MicrophoneParams params) {
        this.params = params;
        input(audioIn(params.queue()), this::onAudio);
    }

    /** The ports of a microphone with these params: the audio input queues {@code queue} chunks. */
    static Ports ports(MicrophoneParams params) {
        return Ports.of(AUDIO_OUT, audioIn(params.queue()));
    }

    private static InputPort<AudioChunk> audioIn(int queue) {
        return InputPort.of("audio", AudioChunk.class, Delivery.queue(queue));
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        AudioFormat in = chunk.format();
        int channels = params.downmix() ? 1 : in.channels();
        if (!in.equals(lastFormat)) {
            lastFormat = in;
            hpPrevIn = new double[channels];
            hpPrevOut = new double[channels];
        }
        double[][] signal = read(chunk, channels);
        highPass(signal, in.sampleRateHz());
        if (params.gate()) {
            gate(signal, in.sampleRateHz());
        }
        AudioFormat outFormat = new AudioFormat(in.sampleRateHz(), channels, 16);
        emit(out, AudioChunk.wrap(outFormat, pcm16(signal)));
    }

    private static double[][] read(AudioChunk chunk, int channels) {
        int inChannels = chunk.format().channels();
        double[][] s = new double[channels][];
        if (channels == inChannels) {
            for (int c = 0; c < channels; c++) {
                s[c] = chunk.channel(c);
            }
            return s;
        }
        double[] mono = new double[chunk.frameCount()];
        for (int c = 0; c < inChannels; c++) {
            double[] ch = chunk.channel(c);
            for (int i = 0; i < mono.length; i++) {
                mono[i] += ch[i] / inChannels;
            }
        }
        s[0] = mono;
        return s;
    }

    private void highPass(double[][] signal, int rateHz) {
        if (params.highPassHz() <= 0) {
            return;
        }
        double rc = 1 / (2 * Math.PI * params.highPassHz());
        double a = rc / (rc + 1.0 / rateHz);
        for (int c = 0; c < signal.length; c++) {
            double[] x = signal[c];
            double prevIn = hpPrevIn[c];
            double prevOut = hpPrevOut[c];
            for (int i = 0; i < x.length; i++) {
                double y = a * (prevOut + x[i] - prevIn);
                prevIn = x[i];
                prevOut = y;
                x[i] = y;
            }
            hpPrevIn[c] = prevIn;
            hpPrevOut[c] = prevOut;
        }
    }

    private void gate(double[][] signal, int rateHz) {
        int frames = signal[0].length;
        int block = Math.max(1, (int) Math.round(params.blockMs() * rateHz / 1000));
        double blockMs = 1000.0 * block / rateHz;
        double rise = 1 - Math.exp(-blockMs / params.floorRiseMs());
        double fall = 1 - Math.exp(-blockMs / FLOOR_FALL_MS);
        double threshold = Math.pow(10, params.gateThresholdDb() / 20);
        double closed = Math.pow(10, params.closedGainDb() / 20);
        for (int start = 0; start < frames; start += block) {
            int end = Math.min(frames, start + block);
            double sum = 0;
            for (double[] ch : signal) {
                for (int i = start; i < end; i++) {
                    sum += ch[i] * ch[i];
                }
            }
            double rms = Math.sqrt(sum / ((end - start) * signal.length));
            boolean loud = floorRms > 0 && rms > floorRms * threshold;
            if (floorRms == 0) {
                floorRms = Math.max(rms, 1e-6);
            } else {
                floorRms += (rms - floorRms) * (rms < floorRms ? fall : rise);
                floorRms = Math.max(floorRms, 1e-6);
            }
            holdLeftMs = loud ? params.holdMs() : Math.max(0, holdLeftMs - blockMs);
            double target = loud || holdLeftMs > 0 ? 1 : closed;
            double step = (target - gain) / (end - start);
            for (int i = start; i < end; i++) {
                gain += step;
                for (double[] ch : signal) {
                    ch[i] *= gain;
                }
            }
            gain = target;
        }
    }

    private static byte[] pcm16(double[][] signal) {
        int channels = signal.length;
        int frames = signal[0].length;
        byte[] pcm = new byte[frames * channels * 2];
        int at = 0;
        for (int i = 0; i < frames; i++) {
            for (double[] ch : signal) {
                long v = Math.round(ch[i] * 32768);
                short s = (short) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v));
                pcm[at++] = (byte) s;
                pcm[at++] = (byte) (s >> 8);
            }
        }
        return pcm;
    }

    /** The noise floor the gate measures against, as an RMS in [0, 1). */
    public double noiseFloorRms() {
        return floorRms;
    }

    /** Makes {@code microphone} methods. */
    public static final class Provider extends SimpleMethodProvider<MicrophoneParams> {
        public Provider() {
            super("microphone", "Removes DC and rumble from microphone audio and gates background noise",
                    MicrophoneParams.class, Microphone::ports, (layer, p) -> new Microphone(p),
                    Layer.SENSORS_ACTUATORS);
        }
    }
}
