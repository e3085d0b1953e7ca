package org.habla.methods.room;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.Param;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;

/**
 * The sound level method, type {@code sound-level}: how loud the room is, from a room microphone's PCM (input
 * {@code audio}, e.g. a {@code pcm-stream} interface) or from a device that measures it itself (input
 * {@code level}, dB). Output {@code levelDb} is the RMS level of every chunk in dB relative to full scale
 * (0 dBFS is the loudest a microphone can take; silence is {@code floorDb}), averaged over all channels, plus
 * {@code offsetDb} (a microphone's calibration to dB SPL). Either input may be left unwired.
 */
public final class SoundLevel extends SensorActuatorMethod {

    private static final InputPort<AudioChunk> AUDIO = InputPort.optional("audio", AudioChunk.class,
            Delivery.queue(64));
    private static final InputPort<NumberValue> LEVEL = InputPort.optional("level", NumberValue.class,
            Delivery.latest());
    private static final OutputPort<NumberValue> LEVEL_DB = OutputPort.of("levelDb", NumberValue.class,
            Shape.number("dB", "the sound level: RMS dB re full scale plus offsetDb"));
    static final Ports PORTS = Ports.of(AUDIO, LEVEL, LEVEL_DB);

    private final Params params;
    private final Output<NumberValue> level = output(LEVEL_DB);

    /**
     * The params of a {@code sound-level} method.
     *
     * @param floorDb  the level of digital silence
     * @param offsetDb added to every level (a calibration)
     */
    public record Params(
            @Param(value = "the level reported for digital silence", unit = "dB", defaultValue = "-100",
                    min = -200, max = 0)
            double floorDb,
            @Param(value = "added to every level, e.g. the microphone's calibration to dB SPL", unit = "dB",
                    defaultValue = "0", min = -200, max = 200) double offsetDb) {

    }

    SoundLevel(Params params) {
        this.params = params;
        input(AUDIO, this::onAudio);
        input(LEVEL, this::onLevel);
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        if (chunk.frameCount() == 0) {
            return;
        }
        double sum = 0;
        long n = 0;
        for (int c = 0; c < chunk.format().channels(); c++) {
            for (double v : chunk.channel(c)) {
                sum += v * v;
                n++;
            }
        }
        double rms = Math.sqrt(sum / n);
        double db = rms <= 0 ? params.floorDb() : Math.max(params.floorDb(), 20 * Math.log10(rms));
        emit(level, new NumberValue(db + params.offsetDb()));
    }

    private void onLevel(NumberValue value, Sample sample) {
        if (Double.isFinite(value.value())) {
            emit(level, new NumberValue(value.value() + params.offsetDb()));
        }
    }

    /** Makes {@code sound-level} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("sound-level", "How loud the room is: RMS dB of a microphone's PCM, or a device's own reading",
                    Params.class, PORTS, (layer, p) -> new SoundLevel(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
