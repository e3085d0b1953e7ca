package org.habla.methods.speech;

import edu.cmu.sphinx.jsgf.JSGFGrammarException;
import edu.cmu.sphinx.jsgf.JSGFGrammarParseException;
import edu.cmu.sphinx.jsgf.JSGFRuleGrammar;
import edu.cmu.sphinx.jsgf.JSGFRuleGrammarFactory;
import edu.cmu.sphinx.jsgf.JSGFRuleGrammarManager;
import edu.cmu.sphinx.jsgf.parser.JSGFParser;
import edu.cmu.sphinx.jsgf.rule.JSGFRule;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleAlternatives;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleCount;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleName;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleSequence;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleTag;
import edu.cmu.sphinx.jsgf.rule.JSGFRuleToken;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * Every phrase of a JSGF grammar, spelt out: the public rules expanded through their alternatives,
 * sequences, optional parts and rule references (tags dropped). An engine that scores each phrase against
 * the sound needs the whole list, so the grammar must be finite: a repeat ({@code *}, {@code +}) or a
 * rule that refers to itself is refused, and so is a grammar of more than {@link #MAX_PHRASES} phrases.
 * Sphinx-4's own JSGF parser reads the file, so both engines read a grammar alike.
 */
final class GrammarExpansion {

    /** The most phrases a grammar may spell: each is scored against every utterance. */
    static final int MAX_PHRASES = 512;
    /** The deepest chain of rule references followed; deeper is taken for a rule that refers to itself. */
    private static final int MAX_DEPTH = 32;

    private GrammarExpansion() {
    }

    /** The phrases of the grammar in {@code file}, lower case, words separated by one space, in grammar order. */
    static List<String> phrases(Path file) throws IOException {
        JSGFRuleGrammar g;
        try {
            g = JSGFParser.newGrammarFromJSGF(file.toUri().toURL(),
                    new JSGFRuleGrammarFactory(new JSGFRuleGrammarManager()));
        } catch (JSGFGrammarParseException e) {
            throw new IOException("the grammar " + file + " cannot be read: " + e.getMessage(), e);
        }
        if (g == null) {
            throw new IOException("the grammar " + file + " cannot be read");
        }
        Set<String> out = new LinkedHashSet<>();
        for (String rule : g.getRuleNames()) {
            if (g.isRulePublic(rule)) {
                for (List<String> words : expand(g, g.getRule(rule), 0, file)) {
                    if (!words.isEmpty()) {
                        out.add(String.join(" ", words));
                    }
                }
            }
        }
        if (out.isEmpty()) {
            throw new IOException("the grammar " + file + " has no phrase (no public rule that spells one)");
        }
        return List.copyOf(out);
    }

    private static List<List<String>> expand(JSGFRuleGrammar g, JSGFRule rule, int depth, Path file)
            throws IOException {
        if (depth > MAX_DEPTH) {
            throw new IOException("the grammar " + file + " refers to a rule within itself: its phrases are endless");
        }
        List<List<String>> out = new ArrayList<>();
        switch (rule) {
            case JSGFRuleToken t -> {
                List<String> words = new ArrayList<>();
                for (String w : t.getText().trim().toLowerCase(Locale.ROOT).split("\\s+")) {
                    if (!w.isEmpty()) {
                        words.add(w);
                    }
                }
                out.add(words);
            }
            case JSGFRuleAlternatives a -> {
                for (JSGFRule r : a.getRules()) {
                    out.addAll(expand(g, r, depth + 1, file));
                }
            }
            case JSGFRuleSequence s -> {
                out.add(List.of());
                for (JSGFRule r : s.getRules()) {
                    List<List<String>> next = new ArrayList<>();
                    for (List<String> tail : expand(g, r, depth + 1, file)) {
                        for (List<String> head : out) {
                            List<String> joined = new ArrayList<>(head);
                            joined.addAll(tail);
                            next.add(joined);
                            limit(next.size(), file);
                        }
                    }
                    out = next;
                }
            }
            case JSGFRuleCount c -> {
                if (c.getCount() != JSGFRuleCount.OPTIONAL) {
                    throw new IOException("the grammar " + file + " repeats a part (* or +): its phrases are endless, "
                            + "and the moonshine engine scores every phrase; spell the repeats out");
                }
                out.add(List.of());
                out.addAll(expand(g, c.getRule(), depth + 1, file));
            }
            case JSGFRuleTag t -> out.addAll(expand(g, t.getRule(), depth + 1, file));
            case JSGFRuleName n -> {
                String name = n.getSimpleRuleName();
                if ("NULL".equals(name)) {
                    out.add(List.of());
                } else if ("VOID".equals(name)) {
                    return out;
                } else {
                    JSGFRule target = resolve(g, n, file);
                    out.addAll(expand(g, target, depth + 1, file));
                }
            }
            default -> throw new IOException("the grammar " + file + " has a part this reader does not know: " + rule);
        }
        limit(out.size(), file);
        return out;
    }

    private static JSGFRule resolve(JSGFRuleGrammar g, JSGFRuleName n, Path file) throws IOException {
        JSGFRule target = g.getRule(n.getSimpleRuleName());
        if (target == null) {
            throw new IOException("the grammar " + file + " refers to <" + n.getSimpleRuleName() + ">, which it lacks");
        }
        return target;
    }

    private static void limit(int phrases, Path file) throws IOException {
        if (phrases > MAX_PHRASES) {
            throw new IOException("the grammar " + file + " spells more than " + MAX_PHRASES + " phrases; the moonshine "
                    + "engine scores every one against each utterance");
        }
    }
}
