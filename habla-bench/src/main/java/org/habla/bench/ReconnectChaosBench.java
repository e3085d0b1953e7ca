package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.ConfigLoader;
import org.habla.config.Reconnect;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.World;
import org.habla.testing.DaemonProcess;

/**
 * A robot that drops and returns: a simulated Pioneer 2 DX is stopped and started again on the same ports
 * {@code outages} times, with outages from 0.2 to 5 s in a shuffled order, while a daemon with the stock
 * {@code pioneer} driver and the default {@code reconnect} settings keeps its ARCOS link. For each outage it
 * prints how long after the robot listens again the link is up (the daemon's status, read every millisecond),
 * the first fresh odometry sample (one comes in every SIP) and the first fresh complete sonar ring (the SIPs
 * carry a few transducers each) reach control clients, and the connect and handshake time of that
 * reconnection. Goal: each link up within {@code initialMs} + one connect.
 */
final class ReconnectChaosBench {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final double SHORTEST_S = 0.2;
    private static final double LONGEST_S = 5.0;

    private final int outages;

    ReconnectChaosBench(int outages) {
        this.outages = outages;
    }

    void run() throws Exception {
        long initialMs = Reconnect.DEFAULTS.initialMs();
        System.out.printf("%nreconnect chaos: a simulated Pioneer stopped and started again %d times on the same ports, "
                + "outages %.1f-%.1f s; pioneer driver, reconnect initialMs %d, maxMs %d%n", outages, SHORTEST_S,
                LONGEST_S, initialMs, Reconnect.DEFAULTS.maxMs());
        int[] ports = DaemonProcess.freePorts(6);
        PioneerSimOptions options = new PioneerSimOptions(World.builtIn("pioneer-room"), 1, 1, ports[0], ports[1],
                ports[2], ports[3], false, PioneerSimOptions.DEFAULT_SONAR_NOISE_M);
        PioneerSim sim = PioneerSim.start(options);
        PluginRegistry registry = PluginRegistry.discover();
        String json = """
                {"system": "reconnect-chaos", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "pioneer", "address": "127.0.0.1:%d"}],
                 "methods": [
                  {"id": "s", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.sonar"},
                   "params": {"kind": "vector"}},
                  {"id": "p", "type": "pass-through", "layer": "processing", "inputs": {"in": "s.out"},
                   "params": {"kind": "vector"}},
                  {"id": "v", "type": "pass-through", "layer": "virtual", "inputs": {"in": "p.out"},
                   "params": {"kind": "vector"}, "expose": {"port": %d, "name": "sonar"}},
                  {"id": "os", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.odometry"},
                   "params": {"kind": "record"}},
                  {"id": "op", "type": "pass-through", "layer": "processing", "inputs": {"in": "os.out"},
                   "params": {"kind": "record"}},
                  {"id": "ov", "type": "pass-through", "layer": "virtual", "inputs": {"in": "op.out"},
                   "params": {"kind": "record"}, "expose": {"port": %d, "name": "odometry"}}]}
                """.formatted(ports[0], ports[4], ports[5]);
        List<Row> rows = new ArrayList<>();
        try (Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
                FreshWatch sonar = new FreshWatch(daemon.port("sonar"));
                FreshWatch odometry = new FreshWatch(daemon.port("odometry"))) {
            await(() -> up(daemon), 20_000, "the first link");
            long startedMicros = EngineClock.system().nowMicros();
            await(() -> sonar.freshSince(startedMicros), 10_000, "fresh sonar");
            System.out.println("  outage    down seen    up after listen    connect    first fresh odometry"
                    + "    first fresh sonar ring");
            for (double outageS : outageList()) {
                long killed = System.nanoTime();
                sim.close();
                await(() -> !up(daemon), 10_000, "the link noticing the robot is gone");
                long downSeen = System.nanoTime();
                sleepUntil(killed + (long) (outageS * 1e9));
                sim = PioneerSim.start(options);
                long listening = System.nanoTime();
                long listeningMicros = EngineClock.system().nowMicros();
                await(() -> up(daemon), 30_000, "the link coming back");
                long linkUp = System.nanoTime();
                await(() -> odometry.freshSince(listeningMicros), 30_000, "fresh odometry after the robot returned");
                await(() -> sonar.freshSince(listeningMicros), 30_000, "a fresh sonar ring after the robot returned");
                double connectMs = daemon.status().path("interfaces").get(0).path("connections").get(0)
                        .path("lastConnectMs").asDouble();
                Row r = new Row(outageS, ms(downSeen - killed), ms(linkUp - listening), connectMs,
                        ms(odometry.firstFreshNanos() - listening), ms(sonar.firstFreshNanos() - listening));
                rows.add(r);
                System.out.printf(Locale.ROOT, "  %5.2f s  %7.1f ms  %12.1f ms  %7.1f ms  %15.1f ms  %17.1f ms%s%n",
                        r.outageS, r.downSeenMs, r.upMs, r.connectMs, r.odometryMs, r.sonarMs,
                        r.upMs <= initialMs + r.connectMs + 1 ? "" : "   (over initialMs + connect)");
            }
        } finally {
            sim.close();
        }
        summarise(rows, initialMs);
    }

    private static void summarise(List<Row> rows, long initialMs) {
        List<Double> up = rows.stream().map(Row::upMs).sorted().toList();
        List<Double> odometry = rows.stream().map(Row::odometryMs).sorted().toList();
        List<Double> sonar = rows.stream().map(Row::sonarMs).sorted().toList();
        List<Double> connect = rows.stream().map(Row::connectMs).sorted().toList();
        long within = rows.stream().filter(r -> r.upMs <= initialMs + r.connectMs + 1).count();
        System.out.printf(Locale.ROOT, "link up after the robot listens again: median %.0f ms, p90 %.0f ms, max %.0f ms%n",
                at(up, 0.5), at(up, 0.9), at(up, 1));
        System.out.printf(Locale.ROOT, "first fresh odometry sample at a control socket: median %.0f ms, p90 %.0f ms, "
                + "max %.0f ms%n", at(odometry, 0.5), at(odometry, 0.9), at(odometry, 1));
        System.out.printf(Locale.ROOT, "first fresh complete sonar ring at a control socket: median %.0f ms, "
                + "p90 %.0f ms, max %.0f ms%n", at(sonar, 0.5), at(sonar, 0.9), at(sonar, 1));
        System.out.printf(Locale.ROOT, "one connect and ARCOS handshake: median %.1f ms, max %.1f ms%n",
                at(connect, 0.5), at(connect, 1));
        System.out.printf("goal, link up within initialMs (%d ms) + one connect (+1 ms of status polling): "
                + "%d of %d outages%n", initialMs, within, rows.size());
    }

    /** {@code outages} outages spread evenly on a log scale from 0.2 to 5 s, in a shuffled order. */
    private List<Double> outageList() {
        List<Double> list = new ArrayList<>();
        for (int i = 0; i < outages; i++) {
            double f = outages == 1 ? 0 : (double) i / (outages - 1);
            list.add(SHORTEST_S * Math.pow(LONGEST_S / SHORTEST_S, f));
        }
        Collections.shuffle(list, new Random(9));
        return list;
    }

    private static boolean up(Daemon daemon) {
        return daemon.status().path("interfaces").get(0).path("up").asBoolean();
    }

    /** The {@code q} quantile of a sorted list: the smallest value with at least that share at or below it. */
    private static double at(List<Double> sorted, double q) {
        return sorted.get(Math.max(0, (int) Math.ceil(q * sorted.size()) - 1));
    }

    private static double ms(long nanos) {
        return nanos / 1e6;
    }

    private static void sleepUntil(long nanoTime) throws InterruptedException {
        long left;
        while ((left = nanoTime - System.nanoTime()) > 0) {
            TimeUnit.NANOSECONDS.sleep(left);
        }
    }

    /** Polls {@code condition} every millisecond for at most {@code millis}. */
    private static void await(BooleanSupplier condition, long millis, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new IllegalStateException("timed out waiting for " + what);
            }
            Thread.sleep(1);
        }
    }

    private record Row(double outageS, double downSeenMs, double upMs, double connectMs, double odometryMs,
            double sonarMs) {
    }

    /** A control client that notes when the first fresh sample taken after a given moment arrives. */
    private static final class FreshWatch implements AutoCloseable {
        private final Socket socket;
        private volatile long sinceMicros = Long.MAX_VALUE;
        private volatile long firstFreshNanos;

        FreshWatch(int port) throws IOException {
            socket = new Socket(InetAddress.getLoopbackAddress(), port);
            Thread.ofPlatform().name("chaos-client").daemon().start(this::read);
        }

        private void read() {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    JsonNode n = JSON.readTree(line);
                    if (n.path("type").asText().equals("sample") && !n.path("stale").asBoolean()
                            && n.path("t").asLong() > sinceMicros && firstFreshNanos == 0) {
                        firstFreshNanos = System.nanoTime();
                    }
                }
            } catch (IOException e) {
                // closed
            }
        }

        /** Whether a fresh sample whose reading was taken after {@code micros} has arrived; starts watching. */
        boolean freshSince(long micros) {
            if (sinceMicros != micros) {
                firstFreshNanos = 0;
                sinceMicros = micros;
            }
            return firstFreshNanos != 0;
        }

        long firstFreshNanos() {
            return firstFreshNanos;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
