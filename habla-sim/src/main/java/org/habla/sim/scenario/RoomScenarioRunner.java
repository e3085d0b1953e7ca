package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.hivemq.client.mqtt.MqttClient;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.habla.sim.room.MosquittoBroker;
import org.habla.sim.room.RoomModel;
import org.habla.sim.room.RoomSimOptions;

/**
 * Runs the room's scenario as a user would deploy it: a Mosquitto broker, the simulated room, the daemon with
 * config/room.json and the control program (examples/room/room_mdb.py), each its own process. The runner sends the
 * teacher in and away through the simulator and measures, on the simulator's ground truth (never on the daemon or
 * the control program), what the lamps did: how many switches were right, how long the person's zone had light when
 * it needed it, and the energy against a room that lit exactly that zone and one that left every lamp on.
 */
final class RoomScenarioRunner {

    /** How a run is set up. */
    record Options(RoomScenarioFile scenario, int episodes, double speed, long seed, Path reportDir, int portOffset,
            Path home) {
    }

    /** One episode's energy over time: [t (s), used, oracle, all on] in Wh since the episode began. */
    record Trace(int episode, double teacherLeftS, List<double[]> points) {
    }

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String[] THIRDS = {"taught, first third", "taught, second third", "taught, last third"};

    private final Options o;
    private final PrintWriter out;
    private final List<Trace> traces = new ArrayList<>();
    private final LinkedBlockingQueue<JsonNode> truth = new LinkedBlockingQueue<>();

    RoomScenarioRunner(Options options, PrintWriter out) {
        this.o = options;
        this.out = out;
    }

    List<Trace> traces() {
        return traces;
    }

    List<RoomPhase> run() throws IOException, InterruptedException {
        RoomScenarioFile sc = o.scenario();
        Files.createDirectories(o.reportDir());
        Path config = o.home().resolve(sc.config());
        Path program = o.home().resolve("examples/room/room_mdb.py");
        if (!Files.isRegularFile(config) || !Files.isRegularFile(program)) {
            throw new IOException("no room config at " + config + " or no control program at " + program);
        }
        Path derived = DerivedConfig.write(config, o.speed(), o.portOffset(), o.reportDir().resolve("daemon-config.json"));
        int brokerPort = 1883 + o.portOffset();
        List<RoomPhase> phases = new ArrayList<>();
        try (Children children = new Children();
                MosquittoBroker broker = MosquittoBroker.start(brokerPort, o.reportDir().resolve("broker"))) {
            say("Mosquitto broker on 127.0.0.1:%d", broker.port());
            Mqtt5AsyncClient watcher = watch(brokerPort);
            try {
                Children.Child sim = children.start("simulator", Children.habla("sim", "room", "--broker",
                        "127.0.0.1:" + brokerPort, "--speed", ScenarioRunner.fmt(o.speed()), "--seed", "" + o.seed(),
                        "--day", ScenarioRunner.fmt(sc.dayS()), "--day-phase", ScenarioRunner.fmt(sc.dayPhase())),
                        o.home(), o.reportDir().resolve("simulator.log"));
                next(Double.NEGATIVE_INFINITY, List.of(sim));
                say("simulated room started (speed %sx, a day is %ss)", ScenarioRunner.fmt(o.speed()),
                        ScenarioRunner.fmt(sc.dayS()));
                Children.Child daemon = children.start("daemon", Children.habla("run", derived.toString(), "--time-scale",
                        ScenarioRunner.fmt(o.speed())), o.home(), o.reportDir().resolve("daemon.log"));
                Map<String, Integer> ports = new java.util.LinkedHashMap<>();
                for (String name : List.of("occupancy", "light", "reward", "action")) {
                    ports.put(name, DerivedConfig.exposedPort(derived, name));
                }
                daemon.awaitPort(ports.get("action"), 120_000);
                say("control program: %s (SHA-256 %s)", o.home().toAbsolutePath().relativize(program.toAbsolutePath()),
                        ScenarioRunner.sha256(program));
                Children.Child control = children.start("control", List.of("python3", "-u", program.toString(),
                        "--occupancy", "" + ports.get("occupancy"), "--light", "" + ports.get("light"),
                        "--reward", "" + ports.get("reward"), "--action", "" + ports.get("action"), "--seed", "" + o.seed(),
                        "--speed", ScenarioRunner.fmt(o.speed()), "--step-s", ScenarioRunner.fmt(sc.stepS()),
                        "--reward-wait-s", ScenarioRunner.fmt(sc.rewardWaitS()),
                        "--absent-after-s", ScenarioRunner.fmt(sc.absentAfterS()),
                        "--log", o.reportDir().resolve("control.jsonl").toString()), o.home(),
                        o.reportDir().resolve("control.log"));
                List<Children.Child> procs = List.of(sim, daemon, control);
                for (int e = 1; e <= o.episodes(); e++) {
                    phases.addAll(episode(e, watcher, procs));
                }
            } finally {
                watcher.disconnect();
            }
        }
        summary(phases);
        return phases;
    }

    private Mqtt5AsyncClient watch(int port) throws IOException {
        Mqtt5AsyncClient c = MqttClient.builder().useMqttVersion5().identifier("habla-scenario-room")
                .serverHost("127.0.0.1").serverPort(port).buildAsync();
        c.publishes(MqttGlobalPublishFilter.SUBSCRIBED, p -> {
            try {
                truth.add(JSON.readTree(p.getPayloadAsBytes()));
            } catch (IOException e) {
                // not ground truth
            }
        });
        try {
            c.connect().get(10, TimeUnit.SECONDS);
            c.subscribeWith().topicFilter(RoomSimOptions.TRUTH_TOPIC).qos(MqttQos.AT_MOST_ONCE).send()
                    .get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new IOException("cannot watch the room's ground truth on the broker: " + e.getMessage(), e);
        }
        return c;
    }

    private void teacher(Mqtt5AsyncClient c, boolean present) {
        c.publishWith().topic(RoomSimOptions.CONTROL_TOPIC).qos(MqttQos.AT_LEAST_ONCE)
                .payload(("{\"teacher\":" + present + "}").getBytes(StandardCharsets.UTF_8)).send();
    }

    private List<RoomPhase> episode(int n, Mqtt5AsyncClient c, List<Children.Child> procs)
            throws IOException, InterruptedException {
        RoomScenarioFile sc = o.scenario();
        teacher(c, true);
        JsonNode s = next(Double.NEGATIVE_INFINITY, procs);
        double t0 = s.path("t").asDouble();
        say("episode %d/%d: the teacher is present for %ss", n, o.episodes(), ScenarioRunner.fmt(sc.teacherS()));
        List<double[]> points = new ArrayList<>();
        double[] cumulative = new double[3];
        List<RoomPhase> phases = new ArrayList<>();
        double taughtEnd = t0 + sc.teacherS();
        double end = taughtEnd + sc.aloneS();
        Phase current = new Phase(n, THIRDS[0], t0);
        int third = 0;
        boolean alone = false;
        double lastSay = t0;
        while (s.path("t").asDouble() < end) {
            JsonNode next = next(s.path("t").asDouble(), procs);
            double t = next.path("t").asDouble();
            current.add(s, next, cumulative);
            points.add(new double[] {t - t0, cumulative[0], cumulative[1], cumulative[2]});
            s = next;
            if (!alone && third < 2 && t >= t0 + (third + 1) * sc.teacherS() / 3) {
                phases.add(current.done(t));
                current = new Phase(n, THIRDS[++third], t);
            } else if (!alone && t >= taughtEnd) {
                phases.add(current.done(t));
                teacher(c, false);
                alone = true;
                current = new Phase(n, "alone", t);
                say("  episode %d  the teacher left at t=%.0fs", n, t - t0);
            }
            if (t - lastSay >= 60) {
                lastSay = t;
                say("  episode %d  %s t=%4.0fs  person in %s  lamps on %s  switches %d (%d right)", n,
                        alone ? "alone " : "taught", t - t0, next.path("person").asText("nobody"),
                        lampsOn(next), current.switches, current.right);
            }
        }
        phases.add(current.done(s.path("t").asDouble()));
        traces.add(new Trace(n, sc.teacherS(), points));
        RoomPhase a = phases.getLast();
        say("  episode %d alone: %d of %d switches right, light %s of the time it was needed, energy %.2f Wh "
                + "(just the needed zone %.2f, every lamp on %.2f)", n, a.right(), a.switches(),
                ScenarioRunner.pct(a.servedFraction()), a.energyWh(), a.oracleWh(), a.allOnWh());
        return phases;
    }

    private static String lampsOn(JsonNode s) {
        List<String> on = new ArrayList<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = s.path("lamps").fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            if (e.getValue().asDouble() > 0) {
                on.add(e.getKey());
            }
        }
        return on.isEmpty() ? "none" : String.join(",", on);
    }

    /** Counts one phase from consecutive truth samples. */
    private static final class Phase {
        final int episode;
        final String name;
        final double start;
        int switches;
        int right;
        double wantedS;
        double servedS;
        double energyWh;
        double oracleWh;
        double allOnWh;

        Phase(int episode, String name, double start) {
            this.episode = episode;
            this.name = name;
            this.start = start;
        }

        void add(JsonNode before, JsonNode after, double[] cumulative) {
            double dt = after.path("t").asDouble() - before.path("t").asDouble();
            double used = total(after.path("energyWh")) - total(before.path("energyWh"));
            int zones = 0;
            int wanting = 0;
            for (Iterator<Map.Entry<String, JsonNode>> it = after.path("lamps").fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                zones++;
                boolean on = e.getValue().asDouble() > 0;
                boolean wasOn = before.path("lamps").path(e.getKey()).asDouble() > 0;
                boolean wants = after.path("wantsLight").path(e.getKey()).asBoolean();
                if (on != wasOn) {
                    switches++;
                    right += on == wants ? 1 : 0;
                }
                if (wants) {
                    wanting++;
                    wantedS += dt;
                    servedS += on ? dt : 0;
                }
            }
            double oracle = wanting * RoomModel.LAMP_WATTS * dt / 3600;
            double allOn = zones * RoomModel.LAMP_WATTS * dt / 3600;
            energyWh += used;
            oracleWh += oracle;
            allOnWh += allOn;
            cumulative[0] += used;
            cumulative[1] += oracle;
            cumulative[2] += allOn;
        }

        RoomPhase done(double end) {
            return new RoomPhase(episode, name, end - start, switches, right, wantedS, servedS, energyWh, oracleWh,
                    allOnWh);
        }

        private static double total(JsonNode energy) {
            double sum = 0;
            for (JsonNode v : energy) {
                sum += v.asDouble();
            }
            return sum;
        }
    }

    /** The next truth sample after simulated time {@code after}; fails if a process died or the room stalled. */
    private JsonNode next(double after, List<Children.Child> procs) throws IOException, InterruptedException {
        long end = System.nanoTime() + 20_000_000_000L;
        while (System.nanoTime() < end) {
            for (Children.Child c : procs) {
                if (!c.alive()) {
                    throw new IOException("the " + c.name() + " stopped (exit " + c.process().exitValue() + "); see "
                            + c.log() + ": " + ScenarioRunner.tail(c.log()));
                }
            }
            JsonNode n = truth.poll(200, TimeUnit.MILLISECONDS);
            if (n != null && n.path("t").asDouble() > after) {
                return n;
            }
        }
        throw new IOException("the simulated room did not advance for 20 s");
    }

    private void summary(List<RoomPhase> phases) {
        say("");
        say("%-8s %-22s %-14s %-14s %-10s %s", "episode", "phase", "switches right", "light needed", "energy",
                "(needed zone / all on)");
        for (RoomPhase p : phases) {
            say("%-8d %-22s %-14s %-14s %-10s %.2f / %.2f Wh", p.episode(), p.phase(),
                    p.switches() == 0 ? "-" : p.right() + "/" + p.switches(), ScenarioRunner.pct(p.servedFraction()),
                    String.format(Locale.ROOT, "%.2f Wh", p.energyWh()), p.oracleWh(), p.allOnWh());
        }
    }

    private void say(String format, Object... args) {
        out.println(String.format(Locale.ROOT, format, args));
        out.flush();
    }
}
