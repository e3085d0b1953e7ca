// Over 300 lines, on purpose: bench/run speech's three parts (the table per engine, enrolment, latency through a
// daemon) read one evaluation set with one chain and print one report.
package org.habla.bench.speech;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.HdrHistogram.Histogram;
import org.habla.bench.Benchmarks;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.config.ParamsJson;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.methods.audio.MonoAudio;
import org.habla.methods.speech.Enrolment;
import org.habla.methods.speech.EvalSet;
import org.habla.methods.speech.SpeechChain;
import org.habla.methods.speech.SpeechRecognitionParams;
import org.habla.methods.speech.StreamScore;
import org.habla.methods.speech.Utterances;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;

/**
 * {@code bench/run speech}: the speech chain of config/aibo.json on the held-out voices of the
 * evaluation set ({@code bench/speech/make-eval-set.sh}): accuracy per condition, rejection of speech
 * outside the grammar, the gain of enrolling each teacher, the real-time factor (in wall time, and in the chain
 * thread's CPU time, which other load on the machine does not change), and — through a
 * daemon with real sockets, the stream played in real time — the latency from the end of speech to the
 * phrase on the socket. Each figure for each engine ({@code --engines sphinx4,moonshine}, the default), the
 * config's chain with only its engine changed. Options: {@code --set DIR} (default target/speech-eval),
 * {@code --config FILE} (default config/aibo.json), {@code --latency-voices N} (default 2),
 * {@code --enrol-voices N} (default 8; enrolment is Sphinx-4's).
 */
public final class SpeechBench {

    private static final int CHUNK_MS = 32;
    /**
     * The in-memory chain decodes on the calling thread (ONNX Runtime on one thread runs there too): its CPU time is
     * the chain's cost whatever else holds the cores.
     */
    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();

    public static void main(String[] args) throws Exception {
        List<String> a = Arrays.asList(args);
        Path set = Path.of(option(a, "--set", "target/speech-eval"));
        Path config = Path.of(option(a, "--config", "config/aibo.json"));
        int latencyVoices = Integer.parseInt(option(a, "--latency-voices", "2"));
        int enrolVoices = Integer.parseInt(option(a, "--enrol-voices", "8"));
        List<EvalSet.Voice> voices = EvalSet.read(set);
        List<EvalSet.Voice> heldOut = voices.stream().filter(EvalSet.Voice::heldOut).toList();
        boolean direct = SpeechChain.direct(new ConfigLoader(PluginRegistry.discover()).load(config).method("speech")
                .orElseThrow());
        System.out.printf("Speech recognition, the chain of %s (%s), on %d held-out voices (%s)%nnever used for tuning; "
                + "%d tune voices not reported here.%n%n", config, direct ? "microphone -> speech-recognition"
                : "audio-processing -> speech-recognition", heldOut.size(),
                String.join(", ", heldOut.stream().map(v -> v.name() + " (" + v.engine() + ")").toList()),
                voices.size() - heldOut.size());
        if (a.contains("--latency-only")) {
            for (String engine : option(a, "--engines", "sphinx4,moonshine").split(",")) {
                latency(config, heldOut.subList(0, Math.min(latencyVoices, heldOut.size())), engine);
            }
            System.exit(0);
        }
        List<String> engines = Arrays.asList(option(a, "--engines", "sphinx4,moonshine").split(","));
        for (String engine : engines) {
            table(config, heldOut, engine);
        }
        if (enrolVoices > 0) {
            adaptation(config, heldOut.subList(0, Math.min(enrolVoices, heldOut.size())));
        }
        if (latencyVoices > 0) {
            for (String engine : engines) {
                latency(config, heldOut.subList(0, Math.min(latencyVoices, heldOut.size())), engine);
            }
        }
        System.exit(0);
    }

    /** The in-memory chain of the config, with {@code engine} as its recogniser, on every held-out stream. */
    private static void table(Path config, List<EvalSet.Voice> heldOut, String engine) throws Exception {
        HablaConfig c = new ConfigLoader(PluginRegistry.discover()).load(config);
        MethodConfig speech = c.method("speech").orElseThrow();
        SpeechChain chain = SpeechChain.of(c.method("audio").orElseThrow().params(),
                ((SpeechRecognitionParams) speech.params()).withEngine(engine), SpeechChain.direct(speech));
        System.out.printf("%nEngine %s (%s)%n", engine, config);
        System.out.printf("%-9s %-22s %-22s %-12s %-10s %-10s %s%n", "condition", "in-grammar right",
                "out-of-grammar silent", "not grammar", "x realtime", "x on CPU", "worst voice");
        StreamScore total = new StreamScore();
        for (String condition : EvalSet.CONDITIONS) {
            StreamScore score = new StreamScore();
            double audioS = 0;
            long busyNs = 0;
            long cpuNs = 0;
            String worst = "";
            double worstAcc = 101;
            for (EvalSet.Voice v : heldOut) {
                if (!v.has(condition)) {
                    continue;
                }
                AudioChunk stream = Utterances.readWav(v.stream(condition));
                long t0 = System.nanoTime();
                long c0 = THREADS.getCurrentThreadCpuTime();
                List<SpeechChain.Heard> heard = chain.run(stream, CHUNK_MS);
                cpuNs += THREADS.getCurrentThreadCpuTime() - c0;
                busyNs += System.nanoTime() - t0;
                audioS += stream.frameCount() / (double) stream.format().sampleRateHz();
                StreamScore s = new StreamScore();
                s.add(v.name(), v.items(), heard, EvalSet.GRAMMAR);
                if (s.accuracy() < worstAcc) {
                    worstAcc = s.accuracy();
                    worst = String.format("%s %.0f%%", v.name(), s.accuracy());
                }
                score.add(s);
            }
            total.add(score);
            System.out.printf("%-9s %4d/%-4d %6.1f %%   %4d/%-4d %6.1f %%   %-12d %-10.1f %-10.1f %s%n", condition,
                    score.inGrammarRight, score.inGrammar, score.accuracy(), score.outOfGrammarRejected,
                    score.outOfGrammar, score.rejection(), score.notInGrammar, audioS / (busyNs / 1e9),
                    audioS / (cpuNs / 1e9), worst);
        }
        System.out.printf("%-9s %4d/%-4d %6.1f %%   %4d/%-4d %6.1f %%   %-12d%n", "all", total.inGrammarRight,
                total.inGrammar, total.accuracy(), total.outOfGrammarRejected, total.outOfGrammar, total.rejection(),
                total.notInGrammar);
        System.out.printf("out of grammar: the grammar's own words alone or out of order (\"go\", \"go left\") %d/%d "
                + "gave nothing, other words and phrases %d/%d; load average %s%n", total.grammarWordItemsRejected,
                total.grammarWordItems, total.outOfGrammarRejected - total.grammarWordItemsRejected,
                total.outOfGrammar - total.grammarWordItems, Benchmarks.loadAverage());
        System.out.printf("resident memory of this process after the %s table: %d MB%n", engine, residentMb());
    }

    /** This process's resident memory (VmRSS), in MB. */
    private static long residentMb() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1024;
                }
            }
        } catch (IOException e) {
            // not on Linux
        }
        return -1;
    }

    /**
     * Each held-out teacher enrols with their first nine in-grammar utterances of the clean stream; both
     * models are then scored on the rest of their utterances, in every condition.
     */
    private static void adaptation(Path config, List<EvalSet.Voice> voices) throws Exception {
        System.out.printf("%nEnrolment (habla enrol) of %d teachers: each one's first 9 clean utterances adapt the model "
                + "(MLLR); scored on their other utterances%n", voices.size());
        System.out.printf("%-9s %-16s %-16s%n", "condition", "as it comes", "enrolled");
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(config);
        SpeechRecognitionParams base = (SpeechRecognitionParams) c.method("speech").orElseThrow().params();
        Record audioParams = c.method("audio").orElseThrow().params();
        SpeechChain plain = SpeechChain.of(audioParams, base, SpeechChain.direct(c.method("speech").orElseThrow()));
        StreamScore[][] scores = new StreamScore[EvalSet.CONDITIONS.size()][2];
        for (StreamScore[] row : scores) {
            row[0] = new StreamScore();
            row[1] = new StreamScore();
        }
        for (EvalSet.Voice v : voices) {
            AudioChunk clean = Utterances.readWav(v.stream("clean"));
            Enrolment enrolment = new Enrolment();
            Set<Integer> used = new HashSet<>();
            List<String> said = new ArrayList<>();
            double[] mono = clean.channel(0);
            for (int i = 0; i < v.items().size() && used.size() < 9; i++) {
                EvalSet.Item item = v.items().get(i);
                if (item.inGrammar()) {
                    int from = (int) Math.max(0, (item.startS() - 0.3) * 16_000);
                    int to = (int) Math.min(mono.length, (item.endS() + 0.3) * 16_000);
                    enrolment.addRecording(MonoAudio.chunk(Arrays.copyOfRange(mono, from, to), 16_000));
                    used.add(i);
                    said.add(item.text());
                }
            }
            Path file = Files.createTempFile("habla-enrol-" + v.name(), ".mllr");
            Enrolment.Outcome o = enrolment.write(base, said, file, true);
            System.out.printf("  %s: enrolment phrases right %d/%d as it comes, %d/%d adapted%n", v.name(), o.rightBefore(),
                    o.phrases(), o.rightAfter(), o.phrases());
            SpeechChain adapted = SpeechChain.of(audioParams, base.withAdaptation(file.toString()),
                    SpeechChain.direct(c.method("speech").orElseThrow()));
            List<EvalSet.Item> rest = new ArrayList<>();
            for (int k = 0; k < EvalSet.CONDITIONS.size(); k++) {
                String condition = EvalSet.CONDITIONS.get(k);
                if (!v.has(condition)) {
                    continue;
                }
                AudioChunk stream = Utterances.readWav(v.stream(condition));
                scores[k][0].add(v.name(), v.items(), plain.run(stream, CHUNK_MS), EvalSet.GRAMMAR, used);
                scores[k][1].add(v.name(), v.items(), adapted.run(stream, CHUNK_MS), EvalSet.GRAMMAR, used);
            }
            Files.deleteIfExists(file);
        }
        for (int k = 0; k < EvalSet.CONDITIONS.size(); k++) {
            System.out.printf("%-9s %5.1f %% (%d)    %5.1f %% (%d)%n", EvalSet.CONDITIONS.get(k), scores[k][0].accuracy(),
                    scores[k][0].inGrammar, scores[k][1].accuracy(), scores[k][1].inGrammar);
        }
    }

    /** Plays held-out streams into a daemon in real time and times each phrase from the end of its speech. */
    private static void latency(Path config, List<EvalSet.Voice> voices, String engine) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(config);
        MethodConfig audio = c.method("audio").orElseThrow();
        MethodConfig speech = c.method("speech").orElseThrow();
        int[] ports = org.habla.testing.DaemonProcess.freePorts(2);
        String json = """
                {"system": "bench-speech", "status": {"port": 0}, "methods": [
                  {"id": "mic", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                   "params": {"kind": "audio", "delivery": "queue", "capacity": 256}, "expose": {"port": %d, "name": "mic"}},
                  {"id": "audio", "type": "audio-processing", "layer": "processing", "inputs": {"audio": "mic.out"},
                   "params": %s},
                  {"id": "speech", "type": "speech-recognition", "layer": "processing", "inputs": {%s},
                   "params": %s},
                  {"id": "words", "type": "pass-through", "layer": "virtual", "inputs": {"in": "speech.words"},
                   "params": {"kind": "text", "delivery": "queue"}, "expose": {"port": %d, "name": "words"}}]}
                """.formatted(ports[0], ParamsJson.write(audio.params()),
                SpeechChain.direct(speech) ? "\"audio\": \"mic.out\"" : "\"segments\": \"audio.segments\"",
                ParamsJson.write(((SpeechRecognitionParams) speech.params()).withEngine(engine)), ports[1]);
        Daemon d = Daemon.start(new ConfigLoader(registry).parse(json, config.toAbsolutePath().getParent()), registry,
                EngineClock.system());
        Histogram h = new Histogram(60_000_000L, 3);
        java.util.Map<String, Histogram> byCondition = new java.util.LinkedHashMap<>();
        int right = 0;
        int items = 0;
        double audioS = 0;
        try (Socket in = connect(d.port("mic")); Socket out = connect(d.port("words"))) {
            ConcurrentLinkedQueue<Object[]> arrivals = new ConcurrentLinkedQueue<>();
            Thread.ofPlatform().daemon().start(() -> {
                try {
                    FrameReader r = new FrameReader(new BufferedInputStream(out.getInputStream()), 1 << 20, 1 << 24);
                    for (Frame f = r.read(); f != null; f = r.read()) {
                        if (f.type().equals("sample")) {
                            arrivals.add(new Object[] {System.nanoTime(), f.header().path("value").asText()});
                        }
                    }
                } catch (IOException e) {
                    // closed
                }
            });
            drainReplies(in);
            FrameWriter w = new FrameWriter(in.getOutputStream());
            long deadline = System.nanoTime() + 120_000_000_000L;
            while (!d.status().toString().contains("\"ready\":true") && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            Thread.sleep(3000); // both methods ready: the model is loaded and warmed up
            for (EvalSet.Voice v : voices) {
                for (String condition : List.of("clean", "noise20")) {
                    AudioChunk stream = Utterances.readWav(v.stream(condition));
                    arrivals.clear();
                    int chunk = 16_000 * CHUNK_MS / 1000 * 2;
                    byte[] pcm = stream.pcm();
                    long t0 = System.nanoTime();
                    for (int at = 0, k = 0; at < pcm.length; at += chunk, k++) {
                        long due = t0 + (long) ((k + 1) * CHUNK_MS * 1e6);
                        long wait = due - System.nanoTime();
                        if (wait > 0) {
                            Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
                        }
                        ObjectNode header = JsonNodeFactory.instance.objectNode().put("op", "write").put("input", "in")
                                .put("kind", "audio").put("rateHz", 16_000).put("channels", 1).put("bits", 16);
                        w.send(new Frame(header, Arrays.copyOfRange(pcm, at, Math.min(pcm.length, at + chunk))));
                    }
                    Thread.sleep(1500);
                    audioS += pcm.length / 32_000.0;
                    List<EvalSet.Item> its = v.items();
                    for (Object[] arrival : arrivals) {
                        double atS = ((Long) arrival[0] - t0) / 1e9;
                        EvalSet.Item last = null;
                        for (EvalSet.Item it : its) {
                            if (it.endS() <= atS) {
                                last = it;
                            }
                        }
                        if (last != null && last.inGrammar() && last.text().equals(arrival[1])) {
                            right++;
                            long micros = Math.max(0, Math.round((atS - last.endS()) * 1e6));
                            h.recordValue(micros);
                            byCondition.computeIfAbsent(condition, k -> new Histogram(60_000_000L, 3)).recordValue(micros);
                        }
                    }
                    items += (int) its.stream().filter(EvalSet.Item::inGrammar).count();
                }
            }
        } finally {
            d.close();
        }
        System.out.printf("%nEngine %s: latency through a daemon (sockets on loopback, %.0f s of held-out clean and noise20 speech "
                + "played in real time in %d ms chunks): end of speech -> phrase on the socket, %d phrases right of %d%n",
                engine, audioS, CHUNK_MS, right, items);
        System.out.printf("p50 %.0f ms   p90 %.0f ms   p99 %.0f ms   max %.0f ms   (speech-recognition fed by %s; "
                + "load average %s)%n", h.getValueAtPercentile(50) / 1e3, h.getValueAtPercentile(90) / 1e3,
                h.getValueAtPercentile(99) / 1e3, h.getMaxValue() / 1e3,
                SpeechChain.direct(speech) ? "the microphone's stream, its own endpointing" : "audio-processing's segments",
                Benchmarks.loadAverage());
        byCondition.forEach((condition, hc) -> System.out.printf("  %-8s %3d phrases right: p50 %.0f ms   p90 %.0f ms   "
                + "max %.0f ms%n", condition, hc.getTotalCount(), hc.getValueAtPercentile(50) / 1e3,
                hc.getValueAtPercentile(90) / 1e3, hc.getMaxValue() / 1e3));
    }

    private static void drainReplies(Socket s) {
        Thread.ofPlatform().daemon().start(() -> {
            try {
                FrameReader r = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 20);
                while (r.read() != null) {
                    // replies to writes: not needed here
                }
            } catch (IOException e) {
                // closed
            }
        });
    }

    private static Socket connect(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setTcpNoDelay(true);
        return s;
    }

    private static String option(List<String> a, String name, String fallback) {
        int at = a.indexOf(name);
        return at >= 0 && at + 1 < a.size() ? a.get(at + 1) : fallback;
    }
}
