package org.habla.methods.speech;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.IntStream;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.method.Layer;
import org.habla.method.MethodHarness;
import org.habla.methods.audio.MonoAudio;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;
import org.habla.sample.Sample;

/**
 * A tool for choosing Moonshine's accept/reject rule: cuts every stream of one split of the evaluation set with the
 * config's {@code audio-processing}, trims and checks each utterance as {@code speech-recognition} does, and writes
 * one JSON line per utterance with the score of every grammar phrase and of each of the grammar's words said alone
 * (log-probability, shortfall from the model's own choice, steps, the worst step's log-probability) and whether it
 * passed the voice check (utterances that fail it are scored too), and one line per stream with its items. Rules
 * are then compared offline on the tune voices ({@code bench/speech/moonshine-rules.py}).
 * {@code MoonshineScores SETDIR SPLIT OUT.jsonl [encoder decoder]}: the model files default to the cache's. It is
 * habla-bench's, in habla-methods' package: it scores with the model's own parts (MoonshineModel, VoiceCheck,
 * UtteranceTrim, GrammarExpansion), which the method keeps to its package.
 */
public final class MoonshineScores {

    private static final int RATE_HZ = 16_000;
    private static final int CHUNK_MS = 32;
    private static final long BASE_MICROS = 1_000_000_000L;

    public static void main(String[] args) throws Exception {
        Path set = Path.of(args[0]);
        String split = args[1];
        Path out = Path.of(args[2]);
        Path folder = MoonshineFiles.defaultFolder();
        MoonshineModel model = args.length > 4 ? MoonshineModel.load(Path.of(args[3]), Path.of(args[4]), 1)
                : MoonshineModel.load(folder, 1);
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(Path.of("config/aibo.json"));
        Record audioParams = c.method("audio").orElseThrow().params();
        MethodProvider<?> audioProvider = registry.method("audio-processing").orElseThrow();
        List<String> phrases = GrammarExpansion.phrases(Path.of("config/grammars/commands.gram"));
        Set<String> words = new LinkedHashSet<>();
        phrases.forEach(p -> words.addAll(List.of(p.split(" "))));
        List<String> rowsText = new ArrayList<>(phrases);
        words.stream().filter(w -> !phrases.contains(w)).forEach(rowsText::add);
        MoonshineTokenizer tokenizer = MoonshineTokenizer.load(folder.resolve("tokenizer.json"));
        int[][] rows = rowsText.stream().map(p -> tokenizer.encode(MoonshineDecoder.sentence(p))).toArray(int[][]::new);
        int[] enders = IntStream.concat(IntStream.of(MoonshineTokenizer.END),
                List.of(".", "!", "?").stream().mapToInt(tokenizer::piece).filter(id -> id >= 0)).toArray();
        VoiceCheck voice = new VoiceCheck(80);
        ObjectMapper json = new ObjectMapper();
        try (BufferedWriter w = Files.newBufferedWriter(out)) {
            ObjectNode head = json.createObjectNode().put("kind", "rows").put("phrases", phrases.size());
            rowsText.forEach(head.putArray("rows")::add);
            w.write(head + "\n");
            for (EvalSet.Voice v : EvalSet.read(set)) {
                if (!v.split().equals(split)) {
                    continue;
                }
                for (String condition : EvalSet.CONDITIONS) {
                    if (!v.has(condition)) {
                        continue;
                    }
                    ObjectNode stream = json.createObjectNode().put("kind", "stream").put("voice", v.name())
                            .put("condition", condition);
                    ArrayNode items = stream.putArray("items");
                    for (EvalSet.Item it : v.items()) {
                        items.addObject().put("start", it.startS()).put("end", it.endS()).put("text", it.text())
                                .put("in", it.inGrammar());
                    }
                    w.write(stream + "\n");
                    AudioChunk audio = Utterances.readWav(v.stream(condition));
                    for (Sample s : segments(audioProvider, audioParams, audio)) {
                        AudioChunk seg = (AudioChunk) s.payload();
                        double[] mono = MonoAudio.resample(MonoAudio.mix(seg), seg.format().sampleRateHz(), RATE_HZ);
                        double[] trimmed = UtteranceTrim.trim(mono, RATE_HZ);
                        ObjectNode u = json.createObjectNode().put("kind", "utterance").put("voice", v.name())
                                .put("condition", condition).put("at", (s.sourceMicros() - BASE_MICROS) / 1e6)
                                .put("ms", trimmed.length * 1000 / RATE_HZ);
                        if (trimmed.length < RATE_HZ / 20) {
                            u.put("skipped", true);
                        } else {
                            u.put("voiced", voice.hasVoice(trimmed, RATE_HZ));
                            float[] x = MoonshineDecoder.normalised(MonoAudio.chunk(trimmed, RATE_HZ));
                            MoonshineModel.RowScore[] scores = model.score(model.encode(x), rows, enders);
                            ArrayNode a = u.putArray("scores");
                            for (MoonshineModel.RowScore r : scores) {
                                a.addArray().add(r.logProb()).add(r.shortfall()).add(r.tokens()).add(r.worstStep());
                            }
                        }
                        w.write(u + "\n");
                    }
                    w.flush();
                    System.out.printf("%s %s %s done (load %.2f)%n", split, v.name(), condition,
                            ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
                }
            }
        }
        System.exit(0);
    }

    private static List<Sample> segments(MethodProvider<?> provider, Record params, AudioChunk stream) {
        MethodHarness audio = MethodHarness.started("audio", create(provider, params)).runBackgroundAtOnce();
        int frame = stream.format().frameBytes();
        int chunkFrames = stream.format().sampleRateHz() * CHUNK_MS / 1000;
        byte[] pcm = stream.pcm();
        double rate = stream.format().sampleRateHz();
        List<Sample> out = new ArrayList<>();
        for (int at = 0; at < stream.frameCount(); at += chunkFrames) {
            int end = Math.min(stream.frameCount(), at + chunkFrames);
            byte[] part = java.util.Arrays.copyOfRange(pcm, at * frame, end * frame);
            audio.push("audio", AudioChunk.wrap(stream.format(), part), BASE_MICROS + Math.round(end / rate * 1e6));
            out.addAll(audio.samples("segments"));
            audio.clear();
        }
        return out;
    }

    private static <P extends Record> org.habla.method.Method create(MethodProvider<P> provider, Record params) {
        return provider.create(Layer.PROCESSING, provider.paramsType().cast(params));
    }
}
