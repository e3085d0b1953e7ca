package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.ExecutorService;
import org.habla.method.Input;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.sample.Sample;

/**
 * One method run outside a graph, on a {@code habla worker}: the engine's own runner (its thread, its
 * bounded input slots, its clock and background pool), fed by {@link #offer} instead of wires, its
 * outputs handed to one listener instead of subscribers. The method code is the same as in the daemon.
 */
public final class HostedMethod implements AutoCloseable {

    private static final long STOP_WAIT_MILLIS = 2_000;

    /** Receives every sample the method publishes. Must not block. */
    @FunctionalInterface
    public interface OutputListener {
        void onSample(String output, Sample sample);
    }

    private final MethodRunner runner;
    private boolean started;

    public HostedMethod(String id, String type, Method method, EngineClock clock, ExecutorService backgroundPool) {
        this.runner = new MethodRunner(id, type, method, clock, backgroundPool, WorkCount.NONE, GraphTap.NONE);
    }

    public List<String> inputNames() {
        return runner.method().inputs().stream().map(Input::name).toList();
    }

    public List<String> outputNames() {
        return runner.method().outputs().stream().map(Output::name).toList();
    }

    /** The kind of payload input {@code name} takes, for reading its samples off the wire. */
    public org.habla.sample.PayloadKind inputKind(String name) {
        return runner.method().input(name).map(Input::kind).orElseThrow(() ->
                new IllegalArgumentException("no input '" + name + "'"));
    }

    /** Tells the method which interface channel an input reads (its metadata); call before {@link #start}. */
    public void bindChannel(String input, org.habla.driver.ChannelDescriptor channel) {
        runner.bindChannel(runner.method().input(input).orElseThrow(() ->
                new IllegalArgumentException("no input '" + input + "'")), channel);
    }

    /** Tells the method which interface channel an output writes; call before {@link #start}. */
    public void bindCommandChannel(String output, org.habla.driver.ChannelDescriptor channel) {
        runner.bindCommandChannel(runner.method().output(output).orElseThrow(() ->
                new IllegalArgumentException("no output '" + output + "'")), channel);
    }

    /** Sends every published sample to {@code listener}; call before {@link #start}. */
    public void onOutput(OutputListener listener) {
        for (Output<?> out : runner.method().outputs()) {
            runner.port(out).subscribe(s -> listener.onSample(out.name(), s));
        }
    }

    public synchronized void start() {
        started = true;
        runner.start();
    }

    /**
     * Hands a sample to input {@code name} as a wire would: never blocks; a full queue drops it.
     *
     * @return false if a full queue dropped it
     * @throws IllegalArgumentException if the method has no such input
     */
    public boolean offer(String name, Sample sample) {
        Input<?> in = runner.method().input(name).orElseThrow(() ->
                new IllegalArgumentException("no input '" + name + "' (inputs: " + String.join(", ", inputNames()) + ")"));
        return runner.slot(in).offer(sample);
    }

    /** Whether the method says it can do its work (e.g. its model is loaded). */
    public boolean ready() {
        return runner.ready();
    }

    /** What the method said about its readiness last, or an empty string. */
    public String readiness() {
        return runner.readinessDetail();
    }

    /** The runner's figures, as the daemon's status shows them. */
    public ObjectNode status(long nowMicros) {
        return runner.status(nowMicros);
    }

    @Override
    public synchronized void close() {
        if (started) {
            started = false;
            runner.stop(STOP_WAIT_MILLIS);
        }
    }
}
