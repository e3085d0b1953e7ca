package org.habla.methods.speech;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * The speech evaluation set made by {@code bench/speech/make-eval-set.sh}: voices, each with streams in
 * several conditions and the times of the items said in them.
 */
public final class EvalSet {

    /** One item of a stream: where its speech starts and ends (s), what was said, and whether the grammar has it. */
    public record Item(double startS, double endS, String text, boolean inGrammar) {
    }

    /** One voice: its name, the engine that spoke it, its split ({@code tune} or {@code held-out}) and its folder. */
    public record Voice(String name, String engine, String split, Path dir, List<Item> items) {

        public boolean heldOut() {
            return split.equals("held-out");
        }

        /** The stream of one condition, or none if the set lacks it. */
        public Path stream(String condition) {
            return dir.resolve(condition + ".wav");
        }

        public boolean has(String condition) {
            return Files.isRegularFile(stream(condition));
        }
    }

    public static final List<String> CONDITIONS = List.of("clean", "noise20", "noise10", "echo", "babble");

    /** The phrases of config/grammars/commands.gram: an item is in the grammar when it says one of them. */
    public static final Set<String> GRAMMAR = Set.of("go forward", "turn left", "turn right", "go back", "stop",
            "good dog", "bad dog", "well done", "no");

    private EvalSet() {
    }

    /** The voices of the set in {@code dir}, in the order of its voices.tsv. */
    public static List<Voice> read(Path dir) throws IOException {
        Path index = dir.resolve("voices.tsv");
        if (!Files.isRegularFile(index)) {
            throw new IOException("no speech evaluation set in " + dir + " (make one with bench/speech/make-eval-set.sh)");
        }
        List<Voice> voices = new ArrayList<>();
        for (String line : Files.readAllLines(index, StandardCharsets.UTF_8)) {
            if (line.isBlank()) {
                continue;
            }
            String[] f = line.split("\t");
            Path vdir = dir.resolve(f[0]);
            List<Item> items = new ArrayList<>();
            for (String l : Files.readAllLines(vdir.resolve("labels.tsv"), StandardCharsets.UTF_8)) {
                if (l.isBlank()) {
                    continue;
                }
                String[] g = l.split("\t");
                items.add(new Item(Double.parseDouble(g[0]), Double.parseDouble(g[1]), g[2], g[3].equals("in")));
            }
            voices.add(new Voice(f[0], f[1], f[2], vdir, List.copyOf(items)));
        }
        return voices;
    }
}
