package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.method.Input;
import org.habla.method.MethodLifecycle;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where a method runs: here in the daemon ({@link Local}), or on a worker with the daemon's copy as a possible
 * fallback ({@link OnWorker}). The method's runner hands every message to its host, on the runner's thread, and
 * does not itself know where the method is.
 */
sealed interface MethodHost {

    /** The graph starts: a method in the daemon starts now; one on a worker does when its worker takes it. */
    void start();

    /** One input sample. */
    void deliver(Input<?> input, Sample sample);

    /** A tick of the method's own period. */
    void tick(long nowMicros);

    /** The engine stopped the robot (or control came back after that). */
    void motionStopped();

    /** The graph stops. */
    void stop();

    /** Adds what the status says of the placement, if there is one. */
    void status(ObjectNode method);

    /** The method object in this daemon, started once; {@code onStarted} starts its ticks. */
    final class Local implements MethodHost {
        private final MethodLifecycle lifecycle;
        private final Runnable onStarted;
        private volatile boolean started;

        Local(MethodLifecycle lifecycle, Runnable onStarted) {
            this.lifecycle = lifecycle;
            this.onStarted = onStarted;
        }

        @Override
        public void start() {
            if (!started) {
                started = true;
                lifecycle.start();
                onStarted.run();
            }
        }

        boolean started() {
            return started;
        }

        @Override
        public void deliver(Input<?> input, Sample sample) {
            lifecycle.deliver(input, sample);
        }

        @Override
        public void tick(long nowMicros) {
            lifecycle.tick(nowMicros);
        }

        @Override
        public void motionStopped() {
            lifecycle.motionStopped();
        }

        @Override
        public void stop() {
            lifecycle.stop();
        }

        @Override
        public void status(ObjectNode method) {
        }
    }

    /**
     * A method placed on a worker: samples go to the worker while it is up; while it is lost they go to the
     * daemon's own copy if the config asks for that fallback (started the first time it is needed), else they are
     * dropped and counted. The worker ticks its copy itself.
     */
    final class OnWorker implements MethodHost {
        private static final Logger LOG = LoggerFactory.getLogger(MethodRunner.class);

        private final String id;
        private final RemotePlacement remote;
        private final Local local;

        OnWorker(String id, RemotePlacement remote, Local local) {
            this.id = id;
            this.remote = remote;
            this.local = local;
        }

        RemotePlacement remote() {
            return remote;
        }

        @Override
        public void start() {
            // the worker's link starts the placement; the daemon's copy waits for a fallback
        }

        /** The worker is lost and the config falls back to the daemon: its copy runs from now on. */
        void fallBack() {
            if (!local.started()) {
                LOG.info("method {} runs in the daemon while its worker {} is lost", id, remote.host());
                local.start();
            }
        }

        @Override
        public void deliver(Input<?> input, Sample sample) {
            if (remote.up()) {
                remote.forward(input, sample);
            } else if (remote.fallsBackToLocal()) {
                fallBack();
                local.deliver(input, sample);
            } else {
                remote.dropWhileLost();
            }
        }

        @Override
        public void tick(long nowMicros) {
            if (!remote.up()) {
                local.tick(nowMicros); // nothing unless the daemon's copy runs
            }
        }

        @Override
        public void motionStopped() {
            if (local.started()) {
                local.motionStopped();
            }
        }

        @Override
        public void stop() {
            if (local.started()) {
                local.stop();
            }
        }

        @Override
        public void status(ObjectNode method) {
            method.set("placement", remote.status());
        }
    }
}
