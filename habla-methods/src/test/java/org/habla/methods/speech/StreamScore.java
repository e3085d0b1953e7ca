package org.habla.methods.speech;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * How well a stream was heard: each item gets what the chain said between its start and the next
 * item's start. An in-grammar item is right when exactly its phrase was said, once; an item outside
 * the grammar is right when nothing was said. Anything said before the first item is a false alarm,
 * and so is any phrase that is not in the grammar.
 */
public final class StreamScore {

    public int inGrammar;
    public int inGrammarRight;
    public int outOfGrammar;
    public int outOfGrammarRejected;
    public int falseAlarms;
    /** Out-of-grammar items made of the grammar's own words only ("go", "go left"), and those that gave nothing. */
    public int grammarWordItems;
    public int grammarWordItemsRejected;
    public int notInGrammar;
    public final List<String> misses = new ArrayList<>();
    /** For each in-grammar item heard right: stream time from the end of its speech to the phrase, in ms. */
    public final List<Double> delaysMs = new ArrayList<>();
    /** Per item: in the grammar?, the phrase said right (if in), and the confidences of what was said. */
    public final List<Object[]> outcomes = new ArrayList<>();

    public void add(String voice, List<EvalSet.Item> items, List<SpeechChain.Heard> heard, Set<String> grammar) {
        add(voice, items, heard, grammar, Set.of());
    }

    /** Scores the stream, leaving out the items whose index is in {@code skip}. */
    public void add(String voice, List<EvalSet.Item> items, List<SpeechChain.Heard> heard, Set<String> grammar,
            Set<Integer> skip) {
        for (SpeechChain.Heard h : heard) {
            if (!grammar.contains(h.phrase())) {
                notInGrammar++;
                misses.add(voice + ": said '" + h.phrase() + "', which is not in the grammar");
            }
            if (items.isEmpty() || h.atS() < items.get(0).startS()) {
                falseAlarms++;
            }
        }
        for (int i = 0; i < items.size(); i++) {
            EvalSet.Item item = items.get(i);
            if (skip.contains(i)) {
                continue;
            }
            double from = item.startS();
            double to = i + 1 < items.size() ? items.get(i + 1).startS() : Double.MAX_VALUE;
            List<SpeechChain.Heard> hs = heard.stream().filter(h -> h.atS() >= from && h.atS() < to).toList();
            List<String> said = hs.stream().map(SpeechChain.Heard::phrase).toList();
            outcomes.add(new Object[] {item.inGrammar(), said.equals(List.of(item.text())),
                    hs.stream().mapToDouble(SpeechChain.Heard::confidence).toArray()});
            if (item.inGrammar()) {
                inGrammar++;
                if (said.equals(List.of(item.text()))) {
                    inGrammarRight++;
                    delaysMs.add((hs.get(0).atS() - item.endS()) * 1000);
                } else {
                    misses.add(voice + ": '" + item.text() + "' -> " + said);
                }
            } else {
                outOfGrammar++;
                Set<String> vocabulary = new java.util.HashSet<>();
                grammar.forEach(p -> vocabulary.addAll(List.of(p.split(" "))));
                boolean ownWords = vocabulary.containsAll(List.of(item.text().split(" ")));
                if (ownWords) {
                    grammarWordItems++;
                }
                if (said.isEmpty()) {
                    outOfGrammarRejected++;
                    if (ownWords) {
                        grammarWordItemsRejected++;
                    }
                } else {
                    misses.add(voice + ": (oog) '" + item.text() + "' -> " + said);
                }
            }
        }
    }

    public void add(StreamScore other) {
        inGrammar += other.inGrammar;
        inGrammarRight += other.inGrammarRight;
        outOfGrammar += other.outOfGrammar;
        outOfGrammarRejected += other.outOfGrammarRejected;
        falseAlarms += other.falseAlarms;
        grammarWordItems += other.grammarWordItems;
        grammarWordItemsRejected += other.grammarWordItemsRejected;
        notInGrammar += other.notInGrammar;
        misses.addAll(other.misses);
        delaysMs.addAll(other.delaysMs);
        outcomes.addAll(other.outcomes);
    }

    /** Accuracy and rejection had everything below {@code t} been left unsaid. */
    public String atThreshold(double t) {
        int in = 0;
        int right = 0;
        int out = 0;
        int rejected = 0;
        for (Object[] o : outcomes) {
            double[] c = (double[]) o[2];
            boolean anyAbove = java.util.Arrays.stream(c).anyMatch(x -> x >= t);
            if ((Boolean) o[0]) {
                in++;
                if ((Boolean) o[1] && c[0] >= t) {
                    right++;
                }
            } else {
                out++;
                if (!anyAbove) {
                    rejected++;
                }
            }
        }
        return String.format("t=%.2f in %.1f%% oog %.1f%%", t, 100.0 * right / Math.max(1, in),
                100.0 * rejected / Math.max(1, out));
    }

    /** The median stream-time delay of the phrases heard right, in ms (NaN if none). */
    public double medianDelayMs() {
        if (delaysMs.isEmpty()) {
            return Double.NaN;
        }
        List<Double> sorted = delaysMs.stream().sorted().toList();
        return sorted.get(sorted.size() / 2);
    }

    public double accuracy() {
        return inGrammar == 0 ? Double.NaN : 100.0 * inGrammarRight / inGrammar;
    }

    public double rejection() {
        return outOfGrammar == 0 ? Double.NaN : 100.0 * outOfGrammarRejected / outOfGrammar;
    }

    @Override
    public String toString() {
        return String.format("in-grammar %d/%d (%.1f%%), out-of-grammar rejected %d/%d (%.1f%%), false alarms %d, "
                + "outside the grammar %d, stream delay p50 %.0f ms; of the grammar's own words %d/%d silent, "
                + "other words %d/%d", inGrammarRight, inGrammar, accuracy(), outOfGrammarRejected, outOfGrammar,
                rejection(), falseAlarms, notInGrammar, medianDelayMs(), grammarWordItemsRejected, grammarWordItems,
                outOfGrammarRejected - grammarWordItemsRejected, outOfGrammar - grammarWordItems);
    }
}
