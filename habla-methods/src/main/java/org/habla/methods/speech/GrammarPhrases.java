package org.habla.methods.speech;

import edu.cmu.sphinx.linguist.dictionary.Word;
import edu.cmu.sphinx.linguist.language.grammar.GrammarArc;
import edu.cmu.sphinx.linguist.language.grammar.GrammarNode;
import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Whether a sequence of words is a whole phrase of a grammar: a walk through Sphinx's grammar graph
 * from its first node to a final one, silences and empty nodes passed over. The recogniser's output
 * goes through it, so what a client reads is always a phrase the grammar has.
 */
final class GrammarPhrases {

    /** A place in the walk: a node reached with the first {@code matched} words spelt. */
    private record At(GrammarNode node, int matched) {
    }

    private final GrammarNode initial;

    GrammarPhrases(GrammarNode initial) {
        this.initial = initial;
    }

    /** True when {@code words} (no silences) spell a path from the first node to a final one. */
    boolean accepts(List<String> words) {
        if (words.isEmpty()) {
            return false;
        }
        ArrayDeque<At> todo = new ArrayDeque<>();
        Set<String> seen = new HashSet<>();
        todo.add(new At(initial, 0));
        while (!todo.isEmpty()) {
            At at = todo.poll();
            if (!seen.add(at.node().getID() + ":" + at.matched())) {
                continue;
            }
            if (at.node().isEmpty()) {
                if (at.matched() == words.size() && at.node().isFinalNode()) {
                    return true;
                }
                follow(at.node(), at.matched(), todo);
                continue;
            }
            for (Word[] alternative : at.node().getAlternatives()) {
                int m = spell(alternative, words, at.matched());
                if (m < 0) {
                    continue;
                }
                if (m == words.size() && at.node().isFinalNode()) {
                    return true;
                }
                follow(at.node(), m, todo);
            }
        }
        return false;
    }

    /** How many words are spelt after this node's words, or -1 if they do not follow on. */
    private static int spell(Word[] alternative, List<String> words, int from) {
        int m = from;
        for (Word w : alternative) {
            if (w.isFiller()) {
                continue;
            }
            if (m >= words.size() || !w.getSpelling().equals(words.get(m))) {
                return -1;
            }
            m++;
        }
        return m;
    }

    private static void follow(GrammarNode node, int matched, ArrayDeque<At> todo) {
        for (GrammarArc arc : node.getSuccessors()) {
            todo.add(new At(arc.getGrammarNode(), matched));
        }
    }
}
