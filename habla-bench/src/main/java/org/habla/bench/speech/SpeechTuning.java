package org.habla.bench.speech;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.bench.Benchmarks;
import org.habla.methods.speech.EvalSet;
import org.habla.methods.speech.SpeechChain;
import org.habla.methods.speech.StreamScore;
import org.habla.methods.speech.Utterances;
import org.habla.sample.AudioChunk;

/**
 * Runs the chain of config/aibo.json over the voices of one split of the evaluation set and prints
 * the score per condition: {@code SpeechTuning SETDIR tune|held-out [condition...]}. A tool for
 * tuning (on the tune voices only); {@code bench/run speech} reports the held-out ones.
 */
public final class SpeechTuning {

    public static void main(String[] args) throws Exception {
        Path set = Path.of(args[0]);
        String split = args[1];
        List<String> conditions = args.length > 2 ? List.of(args).subList(2, args.length) : EvalSet.CONDITIONS;
        SpeechChain chain = SpeechChain.fromConfigWithOverrides(Path.of(System.getProperty("habla.config", "config/aibo.json")),
                "audio", "speech");
        boolean verbose = Boolean.getBoolean("verbose");
        List<Double> decodeMs = new java.util.ArrayList<>();
        StreamScore all = new StreamScore();
        for (String condition : conditions) {
            StreamScore score = new StreamScore();
            Map<String, String> perVoice = new LinkedHashMap<>();
            for (EvalSet.Voice v : EvalSet.read(set)) {
                if (!v.split().equals(split) || !v.has(condition)) {
                    continue;
                }
                AudioChunk stream = Utterances.readWav(v.stream(condition));
                List<SpeechChain.Heard> heard = chain.run(stream, 32);
                heard.forEach(h -> decodeMs.add(h.decodeMs()));
                StreamScore s = new StreamScore();
                s.add(v.name(), v.items(), heard, EvalSet.GRAMMAR);
                perVoice.put(v.name(), s.inGrammarRight + "/" + s.inGrammar + " oog " + s.outOfGrammarRejected + "/"
                        + s.outOfGrammar);
                score.add(s);
                if (verbose) {
                    for (SpeechChain.Heard h : heard) {
                        System.out.printf("  %s %s %.2f %s %.3f%n", condition, v.name(), h.atS(), h.phrase(), h.confidence());
                    }
                }
            }
            System.out.printf("%-8s %s%n         %s%n", condition, score, perVoice);
            StringBuilder roc = new StringBuilder("         ");
            for (double t : new double[] {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4}) {
                roc.append(score.atThreshold(t)).append(" | ");
            }
            System.out.println(roc);
            if (verbose) {
                score.misses.forEach(m -> System.out.println("    miss " + m));
            }
            all.add(score);
        }
        System.out.printf("all      %s%n", all);
        List<Double> sorted = decodeMs.stream().sorted().toList();
        if (!sorted.isEmpty()) {
            System.out.printf("decoding time of the phrases said: p50 %.0f ms, p90 %.0f ms (load average %s)%n",
                    sorted.get(sorted.size() / 2), sorted.get(sorted.size() * 9 / 10), Benchmarks.loadAverage());
        }
        for (double t : new double[] {0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5}) {
            System.out.println("         " + all.atThreshold(t));
        }
        System.exit(0);
    }
}
