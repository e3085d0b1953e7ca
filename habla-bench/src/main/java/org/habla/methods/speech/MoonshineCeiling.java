package org.habla.methods.speech;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.methods.audio.MonoAudio;
import org.habla.plugin.PluginRegistry;

/**
 * What the Moonshine engine can reach on one split of the evaluation set when neither the utterance cutting nor the
 * rejection is to blame: every item is cut at its labelled start and end (with {@value #MARGIN_S} s either side),
 * trimmed as {@code speech-recognition} trims, and decoded by the engine with config/aibo.json's settings. Per
 * condition it prints how often the best phrase is the one said with every phrase said (no threshold), and, for a
 * few thresholds on the confidence, in-grammar right / outside the grammar gave nothing. The engine is loaded as the
 * method loads it ({@link SpeechRecognition#load}).
 * {@code MoonshineCeiling SETDIR tune|held-out}. It is habla-bench's, in habla-methods' package, to reach the
 * engine's parts.
 */
public final class MoonshineCeiling {

    private static final int RATE_HZ = 16_000;
    private static final double MARGIN_S = 0.15;
    private static final double[] THRESHOLDS = {0.05, 0.1, 0.15, 0.2, 0.3};

    /** One item: in the grammar or not, its phrase named right, and the confidence. */
    private record Outcome(boolean inGrammar, boolean right, double confidence) {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 2) {
            System.err.println("usage: MoonshineCeiling SETDIR tune|held-out   (from the repository's root)");
            System.exit(2);
        }
        Path set = Path.of(args[0]);
        String split = args[1];
        List<EvalSet.Voice> voices = EvalSet.read(set).stream().filter(v -> v.split().equals(split)).toList();
        if (voices.isEmpty()) {
            System.err.println("MoonshineCeiling: no voice of split '" + split + "' in " + set + "/voices.tsv");
            System.exit(2);
        }
        HablaConfig c = new ConfigLoader(PluginRegistry.discover()).load(Path.of("config/aibo.json"));
        SpeechRecognitionParams p = (SpeechRecognitionParams) c.method("speech").orElseThrow().params();
        try (SpeechEngine engine = SpeechRecognition.load(p)) {
            List<Outcome> all = new ArrayList<>();
            for (String condition : EvalSet.CONDITIONS) {
                List<Outcome> outcomes = new ArrayList<>();
                for (EvalSet.Voice v : voices) {
                    if (!v.has(condition)) {
                        continue;
                    }
                    double[] stream = Utterances.readWav(v.stream(condition)).channel(0);
                    for (EvalSet.Item it : v.items()) {
                        int from = (int) Math.max(0, (it.startS() - MARGIN_S) * RATE_HZ);
                        int to = (int) Math.min(stream.length, (it.endS() + MARGIN_S) * RATE_HZ);
                        double[] cut = UtteranceTrim.trim(Arrays.copyOfRange(stream, from, to), RATE_HZ);
                        SpeechEngine.Decoded d = engine.decode(MonoAudio.chunk(cut, RATE_HZ)).orElseThrow();
                        outcomes.add(new Outcome(it.inGrammar(), d.phrase().equals(it.text()), d.confidence()));
                    }
                }
                System.out.printf("%-8s %s%n", condition, line(outcomes));
                all.addAll(outcomes);
            }
            System.out.printf("%-8s %s%n", "all", line(all));
            System.out.printf("(%s voices, engine %s, step bonus %s; every phrase said: in-grammar items whose best phrase is right; "
                    + "at t: in-grammar right with confidence >= t / outside the grammar below t)%n", split,
                    engine.name(), p.moonshineStepBonus());
        }
        System.exit(0);
    }

    private static String line(List<Outcome> outcomes) {
        List<Outcome> in = outcomes.stream().filter(Outcome::inGrammar).toList();
        List<Outcome> out = outcomes.stream().filter(o -> !o.inGrammar()).toList();
        long right = in.stream().filter(Outcome::right).count();
        StringBuilder s = new StringBuilder(String.format("every phrase said %d/%d (%.1f %%)", right, in.size(),
                100.0 * right / in.size()));
        for (double t : THRESHOLDS) {
            long kept = in.stream().filter(o -> o.right() && o.confidence() >= t).count();
            long silent = out.stream().filter(o -> o.confidence() < t).count();
            s.append(String.format(" | t=%.2f %.1f/%.1f", t, 100.0 * kept / in.size(), 100.0 * silent / out.size()));
        }
        return s.toString();
    }
}
