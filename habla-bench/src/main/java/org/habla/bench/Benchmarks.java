package org.habla.bench;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * Runs the engine benchmarks and prints their figures: {@code bench/run [latency] [throughput] [fanout] [monitor]
 * [vision] [security] [worker] [mqtt] [--seconds N]} (all by default; the timed ones 10 s each after a warm-up), and the
 * reliability runs of docs/reliability.md with {@code bench/run chaos} (only when named: they take minutes), or
 * its parts {@code hostile} and {@code soak} ({@code --hostile N}, {@code --attack-seconds S},
 * {@code --soak-minutes M}); the daemon's start-up time and resident memory with {@code bench/run footprint}
 * (only when named: minutes; {@code aibo} or {@code pioneer} for one robot, {@code --runs N}, {@code --until S});
 * end of speech to phrase in the Aibo's daemon beside its vision with {@code bench/run aibo-speech} (only when named;
 * {@code --voices N}, {@code --config FILE}, {@code --port-offset N}, {@code --nice N}).
 * {@code fanout --clients N --hz N} runs only the fan-out crowd round, with N readers at N Hz
 * ({@code --reader-threads}: a thread per reader instead of one selector).
 */
public final class Benchmarks {

    private Benchmarks() {
    }

    public static void main(String[] args) throws Exception {
        List<String> list = Arrays.asList(args);
        int seconds = 10;
        int at = list.indexOf("--seconds");
        if (at >= 0 && at + 1 < list.size()) {
            seconds = Integer.parseInt(list.get(at + 1));
        }
        boolean all = list.stream().noneMatch(a -> a.equals("latency") || a.equals("throughput") || a.equals("fanout")
                || a.equals("vision") || a.equals("worker") || a.equals("monitor") || a.equals("recording") || a.equals("mqtt")
                || a.equals("chaos") || a.equals("hostile") || a.equals("soak") || a.equals("security")
                || a.equals("isolation") || a.equals("footprint") || a.equals("aibo-speech"));
        System.out.printf("HABLA engine benchmarks: %d cores, %s %s, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name"), System.getProperty("java.version"), System.getProperty("os.name"));
        System.out.println("load average at start (1, 5, 15 min): " + loadAverage());
        if (all || list.contains("latency")) {
            new LatencyBench(1_000, 3, seconds).run();
        }
        if (all || list.contains("throughput")) {
            new ThroughputBench(3, seconds).run();
        }
        if (list.contains("fanout") && (list.contains("--clients") || list.contains("--hz"))) {
            new FanOutCrowd(option(list, "--clients", 200), option(list, "--hz", 100), 2, seconds,
                    list.contains("--reader-threads")).run();
        } else if (all || list.contains("fanout")) {
            new FanOutBench(2, seconds).run();
        }
        if (all || list.contains("vision")) {
            new VisionBench(2_000).run();
        }
        if (list.contains("recording")) {
            new RecordingBench(seconds).run();
        }
        if (list.contains("monitor")) {
            new MonitorBench(3, seconds, 3).run();
        }
        if (all || list.contains("security")) {
            new SecurityBench(1_000, 3, seconds).run();
        }
        if (all || list.contains("worker")) {
            new WorkerBench(1_000, 3, seconds).run();
        }
        if (all || list.contains("mqtt")) {
            new MqttBench(1_000, 3, seconds).run();
        }
        if (list.contains("isolation")) {
            new IsolationBench(seconds, option(list, "--rounds", 3), list.contains("--without-heavy"),
                    option(list, "--realtime", -1), list.contains("--own-threads")).run();
        }
        if (list.contains("aibo-speech")) {
            int at2 = list.indexOf("--config");
            new AiboSpeechBench(Path.of(at2 >= 0 ? list.get(at2 + 1) : "config/aibo.json"), option(list, "--voices", 2),
                    option(list, "--port-offset", org.habla.sim.PortBlock.freeOffset()), option(list, "--nice", 0)).run();
        }
        if (list.contains("footprint")) {
            List<String> robots = list.stream().filter(a -> a.equals("aibo") || a.equals("pioneer")).toList();
            new FootprintBench(option(list, "--until", 60), option(list, "--runs", 3),
                    robots.isEmpty() ? List.of("aibo", "pioneer") : robots).run();
        }
        if (list.contains("chaos")) {
            new WatchdogChaosBench(20).run();
            new ReconnectChaosBench(20).run();
            new QuietPeerChaosBench(5).run();
        }
        if (list.contains("chaos") || list.contains("hostile")) {
            new HostileClientsBench(option(list, "--hostile", 1_000), option(list, "--attack-seconds", 60)).run();
        }
        if (list.contains("chaos") || list.contains("soak")) {
            new SoakBench(option(list, "--soak-minutes", 10)).run();
        }
        System.out.println("\nload average at end (1, 5, 15 min): " + loadAverage());
        System.exit(0);
    }

    /** The integer after {@code name} in the arguments, or {@code dflt}. */
    private static int option(List<String> args, String name, int dflt) {
        int at = args.indexOf(name);
        return at >= 0 && at + 1 < args.size() ? Integer.parseInt(args.get(at + 1)) : dflt;
    }

    /** The first three fields of /proc/loadavg, or "unknown" off Linux. */
    public static String loadAverage() {
        try {
            String[] f = java.nio.file.Files.readString(java.nio.file.Path.of("/proc/loadavg")).split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (java.io.IOException | RuntimeException e) {
            return "unknown";
        }
    }
}
