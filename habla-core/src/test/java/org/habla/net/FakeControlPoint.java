package org.habla.net;

import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * A small, real control point for tests: it owns a virtual method's ports, lets the test emit samples and flip
 * staleness, records every write, and can be told to reject the next write.
 */
final class FakeControlPoint implements ControlPoint {

    /** A virtual method with an output of every kind and, optionally, control inputs. */
    static final class Ports extends VirtualMethod {
        Ports(boolean withInputs, boolean singleInput) {
            output(OutputPort.of("distance", NumberValue.class, Shape.number("m", "distance to the object")));
            output(OutputPort.of("ranges", VectorValue.class, Shape.vector("m", "ranges")));
            output(OutputPort.of("command", TextValue.class, Shape.text("the teacher's command")));
            output(OutputPort.of("value", RecordValue.class,
                    Shape.record("where the object is", "distanceM", "angleRad", "visible")));
            output(OutputPort.of("audio", AudioChunk.class));
            output(OutputPort.of("camera", ImageFrame.class));
            if (withInputs) {
                input(InputPort.of("action", TextValue.class, Delivery.queue(8)), (v, s) -> { });
                if (!singleInput) {
                    input(InputPort.of("target", VectorValue.class), (v, s) -> { });
                }
            }
        }
    }

    record Written(String input, Payload value) {
    }

    private final String name;
    private final Ports ports;
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    private final Map<String, Sample> latest = new ConcurrentHashMap<>();
    private final AtomicLong seq = new AtomicLong();
    private volatile boolean stale;
    private volatile Rejected rejectNext;
    private volatile ControlLease lease;
    final BlockingQueue<Written> writes = new LinkedBlockingQueue<>();
    final AtomicInteger writersLeft = new AtomicInteger();

    FakeControlPoint(String name, boolean withInputs, boolean singleInput) {
        this.name = name;
        this.ports = new Ports(withInputs, singleInput);
    }

    /** A method with outputs of every kind and two control inputs. */
    static FakeControlPoint twoWay() {
        return new FakeControlPoint("tracker", true, false);
    }

    /** The same, but what is written reaches an actuator: one commander at a time, lapsing after silence. */
    static FakeControlPoint commanded(long lapseMillis) {
        FakeControlPoint p = new FakeControlPoint("tracker", true, false);
        p.lease = new ControlLease(p.name, lapseMillis, () -> System.currentTimeMillis() * 1_000, p::writerLeft,
                line -> p.listeners.forEach(l -> l.onControl(line)));
        return p;
    }

    @Override
    public java.util.Optional<ControlLease> lease() {
        return java.util.Optional.ofNullable(lease);
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public String methodId() {
        return name + "-method";
    }

    @Override
    public Layer layer() {
        return Layer.VIRTUAL;
    }

    @Override
    public List<Output<?>> outputs() {
        return ports.outputs();
    }

    @Override
    public List<Input<?>> controlInputs() {
        return ports.inputs();
    }

    @Override
    public Map<String, Sample> latest() {
        return Map.copyOf(latest);
    }

    @Override
    public boolean stale() {
        return stale;
    }

    @Override
    public Subscription subscribe(Listener listener) {
        listeners.add(listener);
        return () -> listeners.remove(listener);
    }

    @Override
    public void write(Input<?> input, Payload value) throws Rejected {
        Rejected r = rejectNext;
        if (r != null) {
            rejectNext = null;
            throw r;
        }
        writes.add(new Written(input.name(), value));
    }

    @Override
    public void writerLeft() {
        writersLeft.incrementAndGet();
    }

    /** Emits a value on an output, as the engine would, and returns its sequence number. */
    long emit(String output, Payload value) {
        Output<?> out = ports.output(output).orElseThrow();
        long n = seq.incrementAndGet();
        Sample s = new Sample(value, methodId() + "." + output, n, 1_000_000L * n, stale);
        latest.put(output, s);
        for (Listener l : listeners) {
            l.onSample(out, s);
        }
        return s.sequence();
    }

    void stale(boolean isStale, String why) {
        stale = isStale;
        for (Listener l : listeners) {
            l.onStale(isStale, why);
        }
    }

    /** Tells every listener a notice, as a method the socket's values reach would. */
    void notice(org.habla.method.ControlNotice notice) {
        for (Listener l : listeners) {
            l.onNotice(notice);
        }
    }

    void rejectNext(String code, String message) {
        rejectNext = new Rejected(code, message);
    }

    int listenerCount() {
        return listeners.size();
    }
}
