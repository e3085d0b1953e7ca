package org.habla.worker;

import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.zip.CRC32;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.NoParams;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/** Small real methods to place on a worker: a scaler with params, an audio digest, and the daemon's ends. */
final class WorkerTestMethods {

    private WorkerTestMethods() {
    }

    /** Params of {@link Scale}; the constructor refuses a zero factor. */
    record ScaleParams(double factor) {
        ScaleParams {
            if (factor == 0) {
                throw new IllegalArgumentException("factor must not be 0");
            }
        }
    }

    /** Multiplies every number by its factor. */
    static final class Scale extends ProcessingMethod {
        static final Relay<NumberValue> RELAY = relay(NumberValue.class, 4096);
        final Output<NumberValue> out = output(RELAY.out());
        final Input<NumberValue> in;

        Scale(ScaleParams p) {
            in = input(RELAY.in(), (v, s) -> emit(out, new NumberValue(v.value() * p.factor())));
        }
    }

    /** Says how many bytes of PCM it got and their CRC-32, so a test sees the bytes crossed intact. */
    static final class AudioDigest extends ProcessingMethod {
        static final OutputPort<TextValue> DIGEST = OutputPort.of("digest", TextValue.class);
        static final InputPort<AudioChunk> AUDIO = InputPort.of("audio", AudioChunk.class, Delivery.queue(256));
        static final Ports PORTS = Ports.of(AUDIO, DIGEST);
        final Output<TextValue> digest = output(DIGEST);
        final Input<AudioChunk> audio = input(AUDIO, this::on);

        private void on(AudioChunk a, Sample s) {
            CRC32 crc = new CRC32();
            crc.update(a.pcm());
            emit(digest, new TextValue(a.byteCount() + " " + Long.toHexString(crc.getValue()) + " "
                    + a.format().sampleRateHz()));
        }
    }

    /** Says what it knows of the interface channel its input reads: name, unit and metadata. */
    static final class ChannelEcho extends ProcessingMethod {
        static final OutputPort<TextValue> SAID = OutputPort.of("said", TextValue.class);
        static final InputPort<NumberValue> IN = InputPort.of("in", NumberValue.class, Delivery.queue(16));
        static final Ports PORTS = Ports.of(IN, SAID);
        final Output<TextValue> said = output(SAID);
        final Input<NumberValue> in = input(IN, this::on);

        private void on(NumberValue v, Sample s) {
            emit(said, new TextValue(channelOf(in).map(c -> c.name() + " " + c.unit() + " " + c.metadata())
                    .orElse("no channel")));
        }
    }

    /** A control input of any payload passed on (the daemon's way in for the test). */
    static final class Source<P extends Payload> extends VirtualMethod {
        final Output<P> out;
        final Input<P> in;

        Source(Class<P> type) {
            Relay<P> r = relay(type, 256);
            out = output(r.out());
            in = input(r.in(), (v, s) -> emit(out, v), v -> null);
        }
    }

    /** Shows what reaches it on its own output (the daemon's way out for the test). */
    static final class Sink<P extends Payload> extends VirtualMethod {
        final Output<P> out;
        final Input<P> in;

        Sink(Class<P> type) {
            Relay<P> r = relay(type, 256);
            out = output(r.out());
            in = input(r.in(), (v, s) -> emit(out, v));
        }
    }

    /** An input {@code in} (a queue) and an output {@code out} of one type. */
    record Relay<P extends Payload>(InputPort<P> in, OutputPort<P> out) {
        Ports ports() {
            return Ports.of(in, out);
        }
    }

    static <P extends Payload> Relay<P> relay(Class<P> type, int capacity) {
        return new Relay<>(InputPort.of("in", type, Delivery.queue(capacity)), OutputPort.of("out", type));
    }

    record Provider<R extends Record>(String name, Layer layer, Class<R> paramsType, Ports listed,
            Function<R, Method> make) implements MethodProvider<R> {
        @Override
        public String description() {
            return "test method " + name;
        }

        @Override
        public Set<Layer> layers() {
            return Set.of(layer);
        }

        @Override
        public Ports ports(Layer l, R params) {
            return listed;
        }

        @Override
        public Method create(Layer l, R params) {
            return make.apply(params);
        }
    }

    /** Every test type: what a daemon knows. */
    static PluginRegistry all() {
        return PluginRegistry.of(List.of(
                new Provider<>("scale", Layer.PROCESSING, ScaleParams.class, Scale.RELAY.ports(), Scale::new),
                new Provider<>("audio-digest", Layer.PROCESSING, NoParams.class, AudioDigest.PORTS, p -> new AudioDigest()),
                new Provider<>("channel-echo", Layer.PROCESSING, NoParams.class, ChannelEcho.PORTS, p -> new ChannelEcho()),
                new Provider<>("number-source", Layer.VIRTUAL, NoParams.class, relay(NumberValue.class, 256).ports(),
                        p -> new Source<>(NumberValue.class)),
                new Provider<>("number-sink", Layer.VIRTUAL, NoParams.class, relay(NumberValue.class, 256).ports(),
                        p -> new Sink<>(NumberValue.class)),
                new Provider<>("audio-source", Layer.VIRTUAL, NoParams.class, relay(AudioChunk.class, 256).ports(),
                        p -> new Source<>(AudioChunk.class)),
                new Provider<>("text-sink", Layer.VIRTUAL, NoParams.class, relay(TextValue.class, 256).ports(),
                        p -> new Sink<>(TextValue.class))),
                List.of());
    }

    /** A worker that can run the audio digest only. */
    static PluginRegistry audioOnly() {
        return PluginRegistry.of(List.of(
                new Provider<>("audio-digest", Layer.PROCESSING, NoParams.class, AudioDigest.PORTS, p -> new AudioDigest())),
                List.of());
    }
}
