package org.habla.bench;

import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.Body;
import org.habla.sim.world.SimClock;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.habla.testing.DaemonProcess;

/**
 * Chaos benchmark: how long the motion watchdog takes to stop the robot when its control client goes away.
 * The simulated Pioneer runs at real time behind its sockets; the daemon runs {@code config/pioneer.json}
 * against it, with the {@code action} held for 20 s (so only the watchdog, not the end of a label's hold, can
 * stop a silent client's robot). Each trial drives the robot forward until its wheels turn at the cruise speed,
 * then the client either disconnects or stays connected and writes nothing more; a watcher on the simulator's
 * own clock (the robot's side: it sees only the body the ARCOS commands move) notes when braking begins and
 * when both wheels stand still. Every trial after the first also checks that the first write after a stop moves
 * the robot again.
 */
final class WatchdogChaosBench {

    private static final ObjectMapper JSON = new ObjectMapper();
    /** The action's forward speed in config/pioneer.json. */
    private static final double CRUISE_MPS = 0.25;
    private static final long TRIAL_LIMIT_MS = 20_000;

    private final int trials;

    WatchdogChaosBench(int trials) {
        this.trials = trials;
    }

    void run() throws Exception {
        try (PioneerSim sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-hall"), 1));
                TruthClient truth = new TruthClient(sim.truthPort())) {
            PluginRegistry registry = PluginRegistry.discover();
            ObjectNode config = config(sim);
            long watchdogMs = config.path("safety").path("watchdogMs").asLong();
            WheelWatch watch = new WheelWatch(sim.scene().body());
            sim.clock().add(watch);
            try (Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(config.toString()), registry,
                    EngineClock.system())) {
                System.out.printf("%n(chaos) watchdog stop times, measured on the simulated Pioneer's clock (real time): "
                        + "config/pioneer.json, watchdogMs %d, action held 20 s, %d trials each%n", watchdogMs, trials);
                System.out.printf("%-34s %6s %6s | %-26s | %-26s%n", "the control client...", "trials", "failed",
                        "braking begins p50/p90/max", "wheels at zero p50/p90/max");
                System.out.println("(wheels at zero includes braking from 0.25 m/s at the robot's 0.6 m/s², about 420 ms)");
                int port = daemon.port("action");
                measure("disconnects (from its close)", true, 0, port, sim, truth, watch);
                measure("goes silent (last write + " + watchdogMs + " ms)", false, watchdogMs, port, sim, truth, watch);
            }
        }
    }

    /** config/pioneer.json pointed at the simulator, on free ports, with the action held 20 s. */
    private static ObjectNode config(PioneerSim sim) throws IOException {
        ObjectNode c = (ObjectNode) JSON.readTree(Files.readString(Path.of("config/pioneer.json")));
        c.remove("$schema");
        ((ObjectNode) c.path("status")).put("port", 0).put("monitorPort", 0);
        int[] simPorts = {sim.arcosPort(), sim.micPort(), sim.keysPort()};
        for (int i = 0; i < simPorts.length; i++) {
            ((ObjectNode) c.path("interfaces").get(i)).put("address", "127.0.0.1:" + simPorts[i]);
        }
        int[] free = DaemonProcess.freePorts(c.path("methods").size());
        int n = 0;
        for (JsonNode m : c.path("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.path("expose")).put("port", free[n++]);
            }
            if (m.path("id").asText().equals("action")) {
                ((ObjectNode) m.path("params")).put("durationMs", 20_000);
            }
        }
        return c;
    }

    private void measure(String what, boolean disconnect, long subtractMs, int port, PioneerSim sim, TruthClient truth,
            WheelWatch watch) throws Exception {
        List<Double> braking = new ArrayList<>();
        List<Double> still = new ArrayList<>();
        int failed = 0;
        for (int i = 0; i < trials; i++) {
            JsonNode reply = truth.op("{\"op\":\"reset\",\"robot\":{\"xM\":3.0,\"yM\":3.0,\"thetaRad\":0.0}}");
            if (!reply.has("ok")) {
                throw new IllegalStateException("the simulator refused the reset: " + reply);
            }
            try (Client client = new Client(port)) {
                long lastWrite = client.driveToCruise(sim.scene().body());
                if (lastWrite < 0) {
                    failed++;
                    continue;
                }
                long event = disconnect ? System.nanoTime() : lastWrite;
                watch.arm(event);
                if (disconnect) {
                    client.close();
                }
                long[] seen = watch.await(TRIAL_LIMIT_MS);
                if (seen == null) {
                    failed++;
                    continue;
                }
                braking.add((seen[0] - event) / 1e6 - subtractMs);
                still.add((seen[1] - event) / 1e6 - subtractMs);
            }
        }
        System.out.printf("%-34s %6d %6d | %-26s | %-26s%n", what, trials, failed, spread(braking), spread(still));
    }

    private static String spread(List<Double> ms) {
        if (ms.isEmpty()) {
            return "-";
        }
        double[] a = ms.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return String.format("%.0f / %.0f / %.0f ms", a[(a.length - 1) / 2], a[(int) Math.ceil(0.9 * a.length) - 1],
                a[a.length - 1]);
    }

    /** On the simulator's clock: after an event, the first step that brakes and the first that stands still. */
    private static final class WheelWatch implements SimClock.Stepper {
        private final Body body;
        private volatile long armedAt;
        private volatile long brakingAt;
        private volatile long stillAt;

        WheelWatch(Body body) {
            this.body = body;
        }

        void arm(long eventNanos) {
            brakingAt = 0;
            stillAt = 0;
            armedAt = eventNanos;
        }

        @Override
        public void step(double nowS, double dtS) {
            if (armedAt == 0 || stillAt != 0) {
                return;
            }
            long now = System.nanoTime();
            double v = body.forwardMps();
            if (brakingAt == 0 && v < CRUISE_MPS - 1e-6) {
                brakingAt = now;
            }
            if (v == 0 && body.turnRadps() == 0) {
                stillAt = now;
            }
        }

        /** {braking began, wheels at zero} in nanoTime, or null if the robot was still moving after the wait. */
        long[] await(long millis) throws InterruptedException {
            long end = System.nanoTime() + millis * 1_000_000;
            while (stillAt == 0 && System.nanoTime() < end) {
                Thread.sleep(2);
            }
            long[] r = stillAt == 0 ? null : new long[] {brakingAt, stillAt};
            armedAt = 0;
            return r;
        }
    }

    /** A control client of the action socket. */
    private static final class Client implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;
        private int id;

        Client(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(5_000);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), UTF_8));
            in.readLine(); // hello
        }

        /**
         * Writes {@code forward} every 250 ms until the wheels turn at the cruise speed; returns the nanoTime of
         * the last write (the moment the client then falls silent or leaves), or -1 if the robot never got there.
         */
        long driveToCruise(Body body) throws IOException, InterruptedException {
            long end = System.nanoTime() + TRIAL_LIMIT_MS * 1_000_000;
            long last = -1;
            while (System.nanoTime() < end) {
                socket.getOutputStream().write(("{\"value\":\"forward\",\"id\":" + ++id + "}\n").getBytes(UTF_8));
                socket.getOutputStream().flush();
                last = System.nanoTime();
                awaitReply(id);
                long until = last + 250_000_000L;
                while (System.nanoTime() < until) {
                    if (body.forwardMps() >= CRUISE_MPS - 1e-6) {
                        return last;
                    }
                    Thread.sleep(2);
                }
            }
            return -1;
        }

        private void awaitReply(int wanted) throws IOException {
            for (int i = 0; i < 10_000; i++) {
                JsonNode n = JSON.readTree(in.readLine());
                if (n.path("id").asInt(-1) == wanted) {
                    if (!n.path("type").asText().equals("ok")) {
                        throw new IllegalStateException("the write was not taken: " + n);
                    }
                    return;
                }
            }
            throw new IllegalStateException("no answer to write " + wanted);
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
