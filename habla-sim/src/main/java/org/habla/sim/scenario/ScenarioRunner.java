package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Runs a scenario as a user would deploy it: the simulated robot, the daemon with the robot's config
 * and the control program, each its own process, talking over loopback. The runner drives the episodes
 * through the simulator's ground truth — put the robot at its start, let the teacher teach, send the
 * teacher away, watch whether the robot still reaches the object — and measures them. Of the daemon it asks,
 * as an operator would, only whether it is ready (the teacher starts when the robot can hear); it never talks
 * to the control program: what it measures is what the robot did in the simulated world.
 */
final class ScenarioRunner {

    /** How a run is set up. */
    record Options(ScenarioFile scenario, int episodes, double speed, long seed, Path reportDir, int portOffset,
            Path home) {
    }

    /** How long a daemon may take to load its models and reach its robot before a run gives up. */
    private static final long READY_TIMEOUT_MS = 180_000;

    private final Options o;
    private final PrintWriter out;
    private TeacherLog teacherLog;
    private int episode;

    ScenarioRunner(Options options, PrintWriter out) {
        this.o = options;
        this.out = out;
    }

    List<EpisodeResult> run() throws IOException, InterruptedException {
        ScenarioFile sc = o.scenario();
        Files.createDirectories(o.reportDir());
        Path robotConfig = o.home().resolve(sc.config());
        Path mdb = o.home().resolve("examples/mdb/mdb.py");
        if (!Files.isRegularFile(robotConfig)) {
            throw new IOException("no robot config at " + robotConfig);
        }
        if (!Files.isRegularFile(mdb)) {
            throw new IOException("no control program at " + mdb);
        }
        Path derived = DerivedConfig.write(robotConfig, o.speed(), o.portOffset(), o.reportDir().resolve("daemon-config.json"));
        int truthPort = (sc.robot().equals("aibo") ? 10199 : 8199) + o.portOffset();
        List<EpisodeResult> episodes = new ArrayList<>();
        try (Children children = new Children()) {
            List<Children.Child> world = sc.robot().equals("ros2-base")
                    ? Ros2Base.start(children, o.home(), o.reportDir(), sc.world(), o.speed(), o.seed(), o.portOffset(), truthPort)
                    : List.of(children.start("simulator", simCommand(truthPort), o.home(), o.reportDir().resolve("simulator.log")));
            Children.Child sim = world.get(0);
            say("simulated %s started (speed %sx); waiting for its ground truth on port %d", sc.robot(), fmt(o.speed()), truthPort);
            TruthLink link;
            try {
                link = TruthLink.connect(truthPort, 60_000, sim::alive);
            } catch (IOException e) {
                throw new IOException(e.getMessage() + "; see " + sim.log() + ": " + tail(sim.log()), e);
            }
            try (TruthLink truth = link) {
                truth.send(TruthLink.op("teacher").put("present", false));
                Children.Child daemon = children.start("daemon",
                        Children.habla("run", derived.toString(), "--time-scale", fmt(o.speed())), o.home(),
                        o.reportDir().resolve("daemon.log"));
                int[] ports = new int[4];
                String[] names = {"command", "distance_angle", "reward", "action"};
                for (int i = 0; i < 4; i++) {
                    ports[i] = DerivedConfig.exposedPort(derived, names[i]);
                    if (ports[i] < 0) {
                        throw new IOException(robotConfig + " does not expose the control contract's '" + names[i] + "' socket");
                    }
                }
                daemon.awaitPort(ports[1], 120_000);
                long readyFrom = System.nanoTime();
                DaemonReadiness.await(statusPort(derived), READY_TIMEOUT_MS, daemon::alive);
                say("daemon ready: every method ready and every link up (%.1f s after its sockets opened)",
                        (System.nanoTime() - readyFrom) / 1e9);
                say("control program: %s (SHA-256 %s), the same file for every robot", o.home().toAbsolutePath().relativize(mdb.toAbsolutePath()),
                        sha256(mdb));
                say("daemon up: command %d, distance_angle %d, reward %d, action %d", ports[0], ports[1], ports[2], ports[3]);
                Children.Child control = children.start("control", List.of("python3", "-u", mdb.toString(),
                        "--host", "127.0.0.1", "--command-port", "" + ports[0], "--distance-angle-port", "" + ports[1],
                        "--reward-port", "" + ports[2], "--action-port", "" + ports[3], "--seed", "" + o.seed(),
                        "--speed", fmt(o.speed()), "--step-s", fmt(sc.stepS() / o.speed()),
                        "--reward-wait-s", fmt(sc.rewardWaitS() / o.speed()), "--log", o.reportDir().resolve("control.jsonl").toString()),
                        o.home(), o.reportDir().resolve("control.log"));
                long startedAt = System.nanoTime();
                DaemonReadiness.awaitClients(statusPort(derived), List.of(names), READY_TIMEOUT_MS, control::alive);
                say("control program connected to all four sockets (%.1f s after it started)",
                        (System.nanoTime() - startedAt) / 1e9);
                List<Children.Child> watched = new ArrayList<>(world);
                watched.addAll(List.of(daemon, control));
                try (TeacherLog log = new TeacherLog(o.reportDir())) {
                    this.teacherLog = log;
                    for (int e = 1; e <= o.episodes(); e++) {
                        this.episode = e;
                        episodes.add(episode(e, truth, watched));
                    }
                }
            }
        }
        summary(episodes);
        return episodes;
    }

    private List<String> simCommand(int truthPort) throws IOException {
        ScenarioFile sc = o.scenario();
        List<String> args = new ArrayList<>(List.of("sim", sc.robot(), "--world", sc.world(), "--speed", fmt(o.speed()),
                "--seed", "" + o.seed(), "--truth-port", "" + truthPort, "--teacher", "off"));
        if (sc.robot().equals("pioneer")) {
            args.addAll(List.of("--port", "" + (8101 + o.portOffset()), "--mic-port", "" + (8110 + o.portOffset()),
                    "--keys-port", "" + (8111 + o.portOffset())));
        } else {
            args.addAll(List.of("--port-base", "" + (10000 + o.portOffset())));
        }
        return Children.habla(args.toArray(String[]::new));
    }

    private EpisodeResult episode(int n, TruthLink truth, List<Children.Child> procs) throws IOException, InterruptedException {
        ScenarioFile sc = o.scenario();
        List<ScenarioFile.StartPose> starts = sc.starts();
        ScenarioFile.StartPose start = starts.get((n - 1) % starts.size());
        place(truth, start);
        JsonNode s = next(truth, Double.NEGATIVE_INFINITY, procs);
        double t0 = s.path("t").asDouble();
        truth.send(TruthLink.op("teacher").put("present", true));
        say("episode %d/%d: the teacher is present for %ss; robot at (%.2f, %.2f)", n, o.episodes(), fmt(sc.teacherS()),
                start.xM(), start.yM());
        List<DistanceSample> distance = new ArrayList<>();
        List<PhaseObedience> phases = new ArrayList<>();
        double[] thirds = {t0 + sc.teacherS() / 3, t0 + 2 * sc.teacherS() / 3, t0 + sc.teacherS()};
        String[] names = {"taught, first third", "taught, second third", "taught, last third"};
        int third = 0;
        int[] before = {0, 0};
        int reachedWhileTaught = 0;
        int[] base = {0, 0, 0};   // counts before a restart of the teacher's episode counts
        double lastSay = t0;
        while (third < 3) {
            s = next(truth, s.path("t").asDouble(), procs);
            double t = s.path("t").asDouble();
            double d = s.path("distanceM").asDouble();
            distance.add(new DistanceSample(t - t0, d));
            JsonNode tch = s.path("teacher");
            int commands = base[0] + tch.path("commands").asInt();
            int plus = base[1] + tch.path("plus").asInt();
            int minus = base[2] + tch.path("minus").asInt();
            while (third < 3 && t >= thirds[third]) {
                int judged = plus + minus - before[0] - before[1];
                phases.add(new PhaseObedience(names[third], judged, plus - before[0]));
                before = new int[] {plus, minus};
                third++;
            }
            if (third < 3 && d <= sc.reachM()) {
                // Reached while taught: teaching goes on from another start.
                reachedWhileTaught++;
                base = new int[] {commands, plus, minus};
                place(truth, starts.get((n + reachedWhileTaught) % starts.size()));
                s = next(truth, t, procs);
            }
            if (t - lastSay >= 15) {
                lastSay = t;
                say("  episode %d  taught  t=%5.1fs  distance %.2f m  commands %d  rewards +%d −%d", n, t - t0, d,
                        commands, plus, minus);
            }
        }
        truth.send(TruthLink.op("teacher").put("present", false));
        // The robot is put at a fresh start, away from the object, for the phase that counts.
        ScenarioFile.StartPose alone = starts.get((n + starts.size() / 2) % starts.size());
        place(truth, alone);
        s = next(truth, s.path("t").asDouble(), procs);
        double left = s.path("t").asDouble();
        say("  episode %d  the teacher left at t=%.1fs (object reached %d times while taught); robot put at (%.2f, %.2f), "
                + "%.2f m from the object", n, left - t0, reachedWhileTaught, alone.xM(), alone.yM(), s.path("distanceM").asDouble());
        boolean reached = false;
        double reachAfter = Double.NaN;
        while (s.path("t").asDouble() < left + sc.aloneS()) {
            s = next(truth, s.path("t").asDouble(), procs);
            double t = s.path("t").asDouble();
            double d = s.path("distanceM").asDouble();
            distance.add(new DistanceSample(t - t0, d));
            if (d <= sc.reachM()) {
                reached = true;
                reachAfter = t - left;
                break;
            }
            if (t - lastSay >= 15) {
                lastSay = t;
                say("  episode %d  alone   t=%5.1fs  distance %.2f m", n, t - t0, d);
            }
        }
        EpisodeResult r = new EpisodeResult(n, phases, distance, reached, reachAfter);
        int judged = phases.stream().mapToInt(PhaseObedience::commands).sum();
        int obeyed = phases.stream().mapToInt(PhaseObedience::obeyed).sum();
        say("  episode %d: obeyed %d of %d judged commands; %s", n, obeyed, judged,
                reached ? String.format(Locale.ROOT, "reached the object %.1fs after the teacher left", reachAfter)
                        : String.format(Locale.ROOT, "did not reach the object (%.2f m left)", s.path("distanceM").asDouble()));
        return r;
    }

    private static void place(TruthLink truth, ScenarioFile.StartPose p) throws IOException, InterruptedException {
        ObjectNode reset = TruthLink.op("reset");
        reset.putObject("robot").put("xM", p.xM()).put("yM", p.yM()).put("thetaRad", p.thetaRad());
        truth.send(reset);
    }

    /** The next state line after simulated time {@code after}; fails if a process died or the world stalled. */
    private JsonNode next(TruthLink truth, double after, List<Children.Child> procs) throws IOException, InterruptedException {
        long end = System.nanoTime() + 20_000_000_000L;
        while (System.nanoTime() < end) {
            for (Children.Child c : procs) {
                if (!c.alive()) {
                    throw new IOException("the " + c.name() + " stopped (exit " + c.process().exitValue() + "); see " + c.log());
                }
            }
            JsonNode n = truth.awaitTime(Math.nextUp(after), 200);
            if (n != null) {
                if (teacherLog != null) {
                    teacherLog.observe(n, episode);
                }
                return n;
            }
            if (!truth.alive()) {
                throw new IOException("the simulator closed its ground truth");
            }
        }
        throw new IOException("the simulated world did not advance for 20 s");
    }

    /** The status endpoint's port in a derived config. */
    private static int statusPort(Path derivedConfig) throws IOException {
        return new com.fasterxml.jackson.databind.ObjectMapper().readTree(Files.readString(derivedConfig))
                .path("status").path("port").asInt();
    }

    static String sha256(Path file) throws IOException {
        try {
            return java.util.HexFormat.of().formatHex(
                    java.security.MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(file)));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The last lines of a log, for an error message. */
    static String tail(Path log) {
        try {
            List<String> lines = Files.readAllLines(log);
            return String.join(" | ", lines.subList(Math.max(0, lines.size() - 3), lines.size()));
        } catch (IOException e) {
            return "(unreadable)";
        }
    }

    private void summary(List<EpisodeResult> eps) {
        say("");
        say("%-8s %-12s %-12s %-12s %-9s %s", "episode", "obeyed 1/3", "obeyed 2/3", "obeyed 3/3", "reached", "after");
        int reached = 0;
        for (EpisodeResult e : eps) {
            reached += e.reached() ? 1 : 0;
            String[] ob = new String[3];
            for (int i = 0; i < 3; i++) {
                PhaseObedience p = i < e.obedience().size() ? e.obedience().get(i) : null;
                ob[i] = p == null || p.commands() == 0 ? "-" : p.obeyed() + "/" + p.commands();
            }
            say("%-8d %-12s %-12s %-12s %-9s %s", e.episode(), ob[0], ob[1], ob[2], e.reached() ? "yes" : "no",
                    e.reached() ? String.format(Locale.ROOT, "%.1fs", e.timeToReachS()) : "-");
        }
        say("reached after the teacher left: %d of %d episodes (%s)", reached, eps.size(),
                pct(eps.isEmpty() ? Double.NaN : (double) reached / eps.size()));
    }

    static String pct(double x) {
        return Double.isNaN(x) ? "-" : String.format(Locale.ROOT, "%.0f%%", 100 * x);
    }

    static String fmt(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.valueOf(x);
    }

    private void say(String format, Object... args) {
        out.println(String.format(Locale.ROOT, format, args));
        out.flush();
    }
}
