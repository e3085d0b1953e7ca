package org.habla.bench;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.graph.GraphTap;
import org.habla.graph.MethodGraph;
import org.habla.plugin.PluginRegistry;
import org.habla.recording.Recorder;
import org.habla.recording.RecordingHeader;
import org.habla.sample.Sample;
import org.habla.sim.aibo.AiboSimulator;
import org.habla.sim.aibo.TekkotsuPorts;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.World;
import org.habla.testing.DaemonProcess;

/**
 * Benchmark (g): what recording costs, in MCAP and in the line format, for config/pioneer.json and
 * config/aibo.json on their simulators (no control client: the robots' sensor streams, the links, the ticks).
 * One daemon feeds both recorders at once through a tee, so both formats see the very same events; each
 * recorder's writer thread's CPU time is read from the JVM.
 */
final class RecordingBench {

    private final int seconds;

    RecordingBench(int seconds) {
        this.seconds = seconds;
    }

    void run() throws Exception {
        System.out.printf("%n(g) recording cost, %d s of each set-up, both formats fed the same events%n", seconds);
        System.out.printf("%-10s %-12s %10s %10s %10s %12s%n", "set-up", "format", "events", "bytes", "kB/s",
                "writer CPU %");
        Path dir = Files.createTempDirectory("habla-bench-recording");
        try (PioneerSim sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 1))) {
            ObjectNode cfg = config("pioneer.json");
            int[] ports = {sim.arcosPort(), sim.micPort(), sim.keysPort()};
            int i = 0;
            for (var iface : cfg.withArray("interfaces")) {
                ((ObjectNode) iface).put("address", "127.0.0.1:" + ports[i++]);
            }
            measure("pioneer", cfg, dir);
        }
        try (AiboSimulator sim = new AiboSimulator(AiboSimulator.Options.defaults(World.builtIn("aibo-arena"))
                .onFreePorts().withTeacher(true))) {
            sim.start();
            ObjectNode cfg = config("aibo.json");
            TekkotsuPorts p = sim.ports();
            ((ObjectNode) cfg.withArray("interfaces").get(0).get("params")).put("worldStatePort", p.worldState())
                    .put("walkPort", p.walk()).put("headPort", p.head()).put("eStopPort", p.eStop())
                    .put("microphonePort", p.microphone()).put("speakerPort", p.speaker())
                    .put("cameraPort", p.rawCam()).put("controllerPort", p.controller());
            measure("aibo", cfg, dir);
        }
    }

    private void measure(String name, ObjectNode cfgJson, Path dir) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        int[] free = DaemonProcess.freePorts(cfgJson.withArray("methods").size());
        int n = 0;
        for (var m : cfgJson.withArray("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", free[n++]);
            }
        }
        cfgJson.putObject("status").put("port", 0);
        Path configDir = configDir();
        HablaConfig cfg = new ConfigLoader(registry).parse(cfgJson.toString(), configDir);
        EngineClock clock = EngineClock.system();
        RecordingHeader header = new RecordingHeader(clock.nowMicros(), 1, cfgJson, configDir.toString(),
                MethodGraph.channels(cfg, registry));
        Path mcapFile = dir.resolve(name + ".mcap");
        Path lineFile = dir.resolve(name + ".habla-rec");
        try (Recorder mcap = Recorder.create(mcapFile, header, clock);
             Recorder lines = Recorder.create(lineFile, header, clock)) {
            try (Daemon d = Daemon.start(cfg, registry, clock, new Tee(List.of(mcap, lines)))) {
                Thread.sleep(seconds * 1000L);
            }
            mcap.close();
            lines.close();
            report(name, "MCAP", mcap, mcapFile);
            report(name, "line format", lines, lineFile);
        }
    }

    private void report(String name, String format, Recorder r, Path file) throws Exception {
        long bytes = Files.size(file);
        System.out.printf("%-10s %-12s %10d %10d %10.1f %12.2f%n", name, format, r.written(), bytes,
                bytes / 1000.0 / seconds, 100.0 * r.writerCpuNanos() / (seconds * 1e9));
    }

    private static ObjectNode config(String file) throws Exception {
        return (ObjectNode) new ObjectMapper().readTree(Files.readString(configDir().resolve(file)));
    }

    /** The project's config folder, from the project root (bench/run) or a module's folder (tests). */
    private static Path configDir() {
        Path here = Path.of("config/pioneer.json");
        return (Files.exists(here) ? Path.of("config") : Path.of("../config")).toAbsolutePath().normalize();
    }

    /** Hands every event to each of several taps. */
    private record Tee(List<GraphTap> taps) implements GraphTap {
        @Override
        public void reading(String i, String c, Sample s) {
            taps.forEach(t -> t.reading(i, c, s));
        }

        @Override
        public void command(String i, String c, Sample s, boolean sent) {
            taps.forEach(t -> t.command(i, c, s, sent));
        }

        @Override
        public void control(String socket, String input, Sample s) {
            taps.forEach(t -> t.control(socket, input, s));
        }

        @Override
        public void writerLeft(String socket) {
            taps.forEach(t -> t.writerLeft(socket));
        }

        @Override
        public void periodic(String task, long micros, long handled) {
            taps.forEach(t -> t.periodic(task, micros, handled));
        }

        @Override
        public void link(String i, boolean up, long micros) {
            taps.forEach(t -> t.link(i, up, micros));
        }

        @Override
        public void output(String m, String o, Sample s) {
            taps.forEach(t -> t.output(m, o, s));
        }
    }
}
