package org.habla.methods.speech;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.methods.audio.MonoAudio;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;

/**
 * Tuning of enrolment (on the tune voices only): {@code EnrolTuning SETDIR tune|held-out PRIOR,PRIOR,...
 * [condition...]}. Each voice enrols with its first nine clean in-grammar utterances; the model as it
 * comes and each prior's adaptation are scored on the voice's other utterances. It is habla-bench's, in
 * habla-methods' package: it writes adaptations with a prior of its choosing ({@code SphinxDecoder.writeAdaptation},
 * {@code Mllr}), which the method keeps to its package.
 */
public final class EnrolTuning {

    public static void main(String[] args) throws Exception {
        Path set = Path.of(args[0]);
        String split = args[1];
        double[] priors = Arrays.stream(args[2].split(",")).mapToDouble(Double::parseDouble).toArray();
        List<String> conditions = args.length > 3 ? List.of(args).subList(3, args.length) : List.of("clean");
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(Path.of("config/aibo.json"));
        SpeechRecognitionParams base = (SpeechRecognitionParams) c.method("speech").orElseThrow().params();
        Record audioParams = c.method("audio").orElseThrow().params();
        SpeechChain plain = SpeechChain.of(audioParams, base, SpeechChain.direct(c.method("speech").orElseThrow()));
        StreamScore[] total = new StreamScore[priors.length + 1];
        Arrays.setAll(total, i -> new StreamScore());
        for (EvalSet.Voice v : EvalSet.read(set)) {
            if (!v.split().equals(split)) {
                continue;
            }
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
            StringBuilder line = new StringBuilder(v.name());
            List<SpeechChain> chains = new ArrayList<>();
            chains.add(plain);
            for (double prior : priors) {
                Path file = Files.createTempFile("habla-enrol-tune", ".mllr");
                SphinxDecoder.writeAdaptation(SpeechRecognition.settings(base), enrolment.utterances(), said, file, prior);
                Mllr m = Mllr.read(file);
                line.append(String.format(" [prior %.0f: |A-I| %.2f b0 %.2f]", prior, m.distanceFromIdentity(), m.bias(0)[0]));
                chains.add(SpeechChain.of(audioParams, base.withAdaptation(file.toString()),
                    SpeechChain.direct(c.method("speech").orElseThrow())));
            }
            for (int k = 0; k < chains.size(); k++) {
                StreamScore s = new StreamScore();
                for (String condition : conditions) {
                    if (v.has(condition)) {
                        s.add(v.name(), v.items(), chains.get(k).run(Utterances.readWav(v.stream(condition)), 32),
                                EvalSet.GRAMMAR, used);
                    }
                }
                line.append(String.format("  %s %d/%d", k == 0 ? "plain" : "p" + (int) priors[k - 1], s.inGrammarRight,
                        s.inGrammar));
                total[k].add(s);
            }
            System.out.println(line);
        }
        for (int k = 0; k < total.length; k++) {
            System.out.printf("%s: %s%n", k == 0 ? "plain" : "prior " + priors[k - 1], total[k]);
        }
        System.exit(0);
    }
}
