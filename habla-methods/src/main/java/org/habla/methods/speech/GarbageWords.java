package org.habla.methods.speech;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The words that compete with a grammar's phrases and give nothing when they win (a garbage model made of
 * words): each word of the grammar heard on its own or in an order the grammar does not have, and the
 * words of the pronouncing dictionary that sound one phone away from a word of the grammar ("go" against
 * "no", "stock" against "stop"), one word per pronunciation. Words that sound exactly like a word of the
 * grammar are left out: they are the grammar's word as far as any recogniser can tell.
 *
 * <p>{@link #augment} adds them to a JSGF grammar as one more public rule, one of them (with silence
 * around), each with the prior {@code weight}, so a phrase wins only where it fits the sound better than
 * the near misses around it. One word, not a sequence: a loop of hundreds of words makes Sphinx's flat
 * search expand every word's context against every other's, several times slower.
 */
final class GarbageWords {

    /** The public rule the garbage words are added as; a path through it gives nothing. */
    static final String RULE = "hablaGarbage";
    /** How a garbage word is spelt: this, then the word it sounds like. */
    static final String PREFIX = "garbage_";

    private static final Pattern PUBLIC_RULE = Pattern.compile("(?m)^\\s*public\\s+<[^>]+>\\s*=");
    private static final Pattern WORD = Pattern.compile("[a-z][a-z']*");

    private GarbageWords() {
    }

    /** The grammar's words: the tokens of its rule bodies, without rule names, weights, tags and comments. */
    static Set<String> grammarWords(String jsgf) {
        String text = jsgf.replaceAll("(?s)/\\*.*?\\*/", " ").replaceAll("(?m)//.*$", " ");
        Set<String> words = new TreeSet<>();
        for (String statement : text.split(";")) {
            int eq = statement.indexOf('=');
            if (eq < 0 || !statement.contains("<")) {
                continue;
            }
            String body = statement.substring(eq + 1).replaceAll("<[^>]*>", " ").replaceAll("/[^/]*/", " ")
                    .replaceAll("\\{[^}]*\\}", " ").toLowerCase(Locale.ROOT);
            Matcher m = WORD.matcher(body);
            while (m.find()) {
                words.add(m.group());
            }
        }
        return words;
    }

    /**
     * The garbage words for a grammar with these words, from a pronouncing dictionary (word → its
     * pronunciations): each a word of its own ({@link #PREFIX} and the word it sounds like) with its
     * pronunciation, so a path through them is told from the grammar's own by its words alone.
     */
    static Map<String, List<String>> of(Set<String> grammarWords, Map<String, List<List<String>>> dictionary) {
        Set<List<String>> grammarSounds = new HashSet<>();
        Map<String, List<String>> out = new TreeMap<>();
        for (String w : grammarWords) {
            List<List<String>> prons = dictionary.getOrDefault(w, List.of());
            grammarSounds.addAll(prons);
            for (int i = 0; i < prons.size(); i++) {
                out.put(PREFIX + w + (i == 0 ? "" : "_" + (i + 1)), prons.get(i));
            }
        }
        Set<List<String>> taken = new HashSet<>(grammarSounds);
        for (Map.Entry<String, List<List<String>>> e : new TreeMap<>(dictionary).entrySet()) {
            String word = e.getKey();
            if (!word.chars().allMatch(c -> c >= 'a' && c <= 'z') || grammarWords.contains(word)) {
                continue;
            }
            List<List<String>> prons = e.getValue();
            for (int i = 0; i < prons.size(); i++) {
                List<String> p = prons.get(i);
                if (!taken.contains(p) && grammarSounds.stream().anyMatch(g -> oneApart(p, g))) {
                    taken.add(p);
                    out.put(PREFIX + word + (i == 0 ? "" : "_" + (i + 1)), p);
                }
            }
        }
        return out;
    }

    /** Whether a word the recogniser heard is a garbage word. */
    static boolean isGarbage(String word) {
        return word.startsWith(PREFIX);
    }

    /** The garbage words as a Sphinx dictionary addendum ({@code word PH PH ...} per line). */
    static String addendum(Map<String, List<String>> garbage) {
        StringBuilder b = new StringBuilder();
        garbage.forEach((w, p) -> b.append(w).append(' ').append(String.join(" ", p)).append('\n'));
        return b.toString();
    }

    /** True when one phone substituted, inserted or deleted turns {@code a} into {@code b}. */
    static boolean oneApart(List<String> a, List<String> b) {
        if (Math.abs(a.size() - b.size()) > 1) {
            return false;
        }
        if (a.size() == b.size()) {
            int diff = 0;
            for (int i = 0; i < a.size() && diff < 2; i++) {
                if (!a.get(i).equals(b.get(i))) {
                    diff++;
                }
            }
            return diff == 1;
        }
        List<String> shorter = a.size() < b.size() ? a : b;
        List<String> longer = a.size() < b.size() ? b : a;
        for (int i = 0; i < longer.size(); i++) {
            List<String> without = new ArrayList<>(longer.subList(0, i));
            without.addAll(longer.subList(i + 1, longer.size()));
            if (without.equals(shorter)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The grammar with the garbage words added: a public rule of one or more of them, each word with
     * prior {@code weight} (the rest of the rule's weight goes nowhere).
     */
    static String augment(String jsgf, Set<String> garbage, double weight) {
        if (weight <= 0) {
            return jsgf;
        }
        if (garbage.isEmpty() || !PUBLIC_RULE.matcher(jsgf).find()) {
            return jsgf;
        }
        double rest = Math.max(0, 1 - weight * garbage.size());
        StringBuilder rule = new StringBuilder("\n\n// added by HABLA: near misses of the grammar, which give nothing\n");
        rule.append("public <").append(RULE).append("> = <").append(RULE).append("Word>;\n");
        rule.append("<").append(RULE).append("Word> =");
        String w = String.format(Locale.ROOT, "/%.6g/", weight);
        boolean first = true;
        for (String g : garbage) {
            rule.append(first ? " " : "\n    | ").append(w).append(' ').append(g);
            first = false;
        }
        if (rest > 0) {
            rule.append(String.format(Locale.ROOT, "\n    | /%.6g/ <VOID>", rest));
        }
        rule.append(";\n");
        return jsgf + rule;
    }

    /** Reads a Sphinx pronouncing dictionary ({@code word PH PH ...}, alternatives as {@code word(2)}). */
    static Map<String, List<List<String>>> readDictionary(InputStream in) throws IOException {
        Map<String, List<List<String>>> dict = new HashMap<>();
        Map<String, String> phones = new HashMap<>();   // some forty phones, one String each
        try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                String[] f = line.trim().split("\\s+");
                if (f.length < 2) {
                    continue;
                }
                String word = f[0].replaceFirst("\\(\\d+\\)$", "");
                String[] pron = Arrays.copyOfRange(f, 1, f.length);
                for (int i = 0; i < pron.length; i++) {
                    pron[i] = phones.computeIfAbsent(pron[i], p -> p);
                }
                dict.computeIfAbsent(word, k -> new ArrayList<>(1)).add(List.of(pron));
            }
        }
        return dict;
    }
}
