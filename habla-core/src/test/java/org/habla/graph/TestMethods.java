package org.habla.graph;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.NoParams;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;

/** Small real methods for engine tests: a doubling chain, a slow method, a ticking counter. */
final class TestMethods {

    private TestMethods() {
    }

    static final OutputPort<NumberValue> OUT = OutputPort.of("out", NumberValue.class);
    static final OutputPort<NumberValue> COUNT = OutputPort.of("count", NumberValue.class);

    /** A number input {@code in} with a queue of {@code capacity}. */
    static InputPort<NumberValue> in(int capacity) {
        return InputPort.of("in", NumberValue.class, Delivery.queue(capacity));
    }

    /** The ports {@code in} (a queue of {@code capacity}) and {@code out}. */
    static Ports relay(int capacity) {
        return Ports.of(in(capacity), OUT);
    }

    /** Adds one to every number; queue delivery so nothing is conflated. */
    static final class AddOneSensor extends SensorActuatorMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(4096), this::on);

        private void on(NumberValue v, Sample s) {
            emit(out, new NumberValue(v.value() + 1));
        }
    }

    static final class AddOneProcessing extends ProcessingMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(4096), this::on);

        private void on(NumberValue v, Sample s) {
            emit(out, new NumberValue(v.value() + 1));
        }
    }

    static final class AddOneVirtual extends VirtualMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(4096), this::on);

        private void on(NumberValue v, Sample s) {
            emit(out, new NumberValue(v.value() + 1));
        }
    }

    /** Takes a value from control and sends it down as a command; refuses values beyond ±100. */
    static final class CommandVirtual extends VirtualMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(64), this::on,
                v -> Math.abs(v.value()) <= 100 ? null : "a command must be within ±100, was " + v.value());

        private void on(NumberValue v, Sample s) {
            emit(out, v);
        }
    }

    static final class ForwardProcessing extends ProcessingMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(64), this::on);

        private void on(NumberValue v, Sample s) {
            emit(out, v);
        }
    }

    /** Hands values to its command channel; tells in its readiness which channel that is. */
    static final class ForwardActuator extends SensorActuatorMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(64), this::on);

        @Override
        protected void onStart() {
            readiness(true, commandChannelOf(out).map(c -> "writes " + c.name() + " in " + c.unit()).orElse("writes nothing"));
        }

        private void on(NumberValue v, Sample s) {
            emit(out, v);
        }
    }

    /**
     * Holds every sample until the test opens its {@link #gate}, as a long recognition holds its thread: while it
     * is {@link #busy}, the test can show what goes on without it. Gives up after {@link #HOLD_LIMIT_S}.
     */
    static final class SlowProcessing extends ProcessingMethod {
        static final long HOLD_LIMIT_S = 60;
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(InputPort.of("in", NumberValue.class), this::on);
        final CountDownLatch gate = new CountDownLatch(1);
        volatile boolean busy;

        private void on(NumberValue v, Sample s) {
            busy = true;
            try {
                gate.await(HOLD_LIMIT_S, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                busy = false;
            }
            emit(out, v);
        }
    }

    /** Takes values from control into a queue of 64 and holds each until the test opens its {@link #gate}. */
    static final class GatedVirtual extends VirtualMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(64), this::on);
        final CountDownLatch gate = new CountDownLatch(1);

        private void on(NumberValue v, Sample s) {
            try {
                gate.await(SlowProcessing.HOLD_LIMIT_S, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            emit(out, v);
        }
    }

    /** Emits a running count on every tick. */
    static final class Ticker extends ProcessingMethod {
        final Output<NumberValue> count = output(COUNT);
        private int n;

        Ticker() {
            tickEvery(Duration.ofMillis(100));
        }

        @Override
        protected void onTick(long nowMicros) {
            emit(count, new NumberValue(++n));
        }
    }

    /** Adds what comes in on {@code a} and on {@code b}, each sample as it comes, to a running sum. */
    static final class SumProcessing extends ProcessingMethod {
        static final InputPort<NumberValue> A = InputPort.of("a", NumberValue.class, Delivery.queue(64));
        static final InputPort<NumberValue> B = InputPort.of("b", NumberValue.class, Delivery.queue(64));
        static final Ports PORTS = Ports.of(A, B, OUT);
        final Output<NumberValue> out = output(OUT);
        private double sum;

        SumProcessing() {
            input(A, this::on);
            input(B, this::on);
        }

        private void on(NumberValue v, Sample s) {
            sum += v.value();
            emit(out, new NumberValue(sum));
        }
    }

    /** Counts the link records it is handed. */
    static final class LinkCounter extends SensorActuatorMethod {
        static final InputPort<org.habla.sample.RecordValue> LINK =
                InputPort.of("link", org.habla.sample.RecordValue.class);
        static final Ports PORTS = Ports.of(LINK, COUNT);
        final Output<NumberValue> count = output(COUNT);
        private int n;

        LinkCounter() {
            input(LINK, (v, s) -> emit(count, new NumberValue(++n)));
        }
    }

    /** Hands every number to background work, and emits it when the work is done. */
    static final class Backgrounder extends ProcessingMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(16), this::on);

        private void on(NumberValue v, Sample s) {
            background("echo", () -> v, done -> emit(out, done));
        }
    }

    /** Throws on a negative number. */
    static final class Fragile extends ProcessingMethod {
        final Output<NumberValue> out = output(OUT);
        final Input<NumberValue> in = input(in(16), this::on);

        private void on(NumberValue v, Sample s) {
            if (v.value() < 0) {
                throw new IllegalArgumentException("negative");
            }
            emit(out, v);
        }
    }

    /** A test type; {@code light} ones may run on the thread that delivers to them. */
    record Simple(String name, Layer layer, Ports listed, java.util.function.Supplier<Method> make, boolean light)
            implements MethodProvider<NoParams> {

        Simple(String name, Layer layer, Ports listed, java.util.function.Supplier<Method> make) {
            this(name, layer, listed, make, false);
        }

        @Override
        public String description() {
            return "test method " + name;
        }

        @Override
        public Set<Layer> layers() {
            return Set.of(layer);
        }

        @Override
        public Class<NoParams> paramsType() {
            return NoParams.class;
        }

        @Override
        public Ports ports(Layer l, NoParams params) {
            return listed;
        }

        @Override
        public Method create(Layer l, NoParams params) {
            return make.get();
        }
    }

    static PluginRegistry registry() {
        return PluginRegistry.of(List.of(
                new Simple("add-one-sensor", Layer.SENSORS_ACTUATORS, relay(4096), AddOneSensor::new),
                new Simple("add-one-processing", Layer.PROCESSING, relay(4096), AddOneProcessing::new),
                new Simple("add-one-virtual", Layer.VIRTUAL, relay(4096), AddOneVirtual::new),
                new Simple("command-virtual", Layer.VIRTUAL, relay(64), CommandVirtual::new),
                new Simple("forward-processing", Layer.PROCESSING, relay(64), ForwardProcessing::new),
                new Simple("forward-actuator", Layer.SENSORS_ACTUATORS, relay(64), ForwardActuator::new),
                new Simple("slow", Layer.PROCESSING, Ports.of(InputPort.of("in", NumberValue.class), OUT),
                        SlowProcessing::new),
                new Simple("gated-virtual", Layer.VIRTUAL, relay(64), GatedVirtual::new),
                new Simple("ticker", Layer.PROCESSING, Ports.of(COUNT), Ticker::new),
                new Simple("fragile", Layer.PROCESSING, relay(16), Fragile::new),
                new Simple("add-one-sensor-light", Layer.SENSORS_ACTUATORS, relay(4096), AddOneSensor::new, true),
                new Simple("add-one-processing-light", Layer.PROCESSING, relay(4096), AddOneProcessing::new, true),
                new Simple("add-one-virtual-light", Layer.VIRTUAL, relay(4096), AddOneVirtual::new, true),
                new Simple("forward-processing-light", Layer.PROCESSING, relay(64), ForwardProcessing::new, true),
                new Simple("fragile-light", Layer.PROCESSING, relay(16), Fragile::new, true),
                new Simple("ticker-light", Layer.PROCESSING, Ports.of(COUNT), Ticker::new, true),
                new Simple("sum-light", Layer.PROCESSING, SumProcessing.PORTS, SumProcessing::new, true),
                new Simple("background-light", Layer.PROCESSING, relay(16), Backgrounder::new, true),
                new Simple("link-counter-light", Layer.SENSORS_ACTUATORS, LinkCounter.PORTS, LinkCounter::new, true)),
                List.of(new LineDriver.Provider(), new LineDriver.PairProvider()));
    }
}
