package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import edu.cmu.sphinx.linguist.dictionary.Pronunciation;
import edu.cmu.sphinx.linguist.dictionary.Word;
import edu.cmu.sphinx.linguist.language.grammar.GrammarNode;
import java.util.List;
import org.junit.jupiter.api.Test;

class GrammarPhrasesTest {

    private static int ids;

    private static GrammarNode node(String... words) {
        Word[][] alternatives = words.length == 0 ? new Word[0][] : new Word[][] {
                java.util.Arrays.stream(words).map(w -> new Word(w, new Pronunciation[0], w.startsWith("<"))).toArray(Word[]::new)};
        return new GrammarNode(ids++, alternatives);
    }

    /** start → (turn → (left | right) | stop | go → <sil> → back) → end, as Sphinx builds a grammar's graph. */
    private static GrammarPhrases grammar() {
        GrammarNode start = node();
        GrammarNode end = node();
        end.setFinalNode(true);
        GrammarNode turn = node("turn");
        GrammarNode left = node("left");
        GrammarNode right = node("right");
        GrammarNode stop = node("stop");
        GrammarNode go = node("go");
        GrammarNode sil = node("<sil>");
        GrammarNode back = node("back");
        start.add(turn, 0);
        turn.add(left, 0);
        turn.add(right, 0);
        left.add(end, 0);
        right.add(end, 0);
        start.add(stop, 0);
        stop.add(end, 0);
        start.add(go, 0);
        go.add(sil, 0);
        sil.add(back, 0);
        back.add(end, 0);
        return new GrammarPhrases(start);
    }

    @Test
    void wholePhrasesAreAcceptedAndSilencesPassedOver() {
        GrammarPhrases g = grammar();
        assertThat(g.accepts(List.of("turn", "left"))).isTrue();
        assertThat(g.accepts(List.of("stop"))).isTrue();
        assertThat(g.accepts(List.of("go", "back"))).isTrue();
    }

    @Test
    void aPhraseCutShortOrRunOnIsNotAPhraseOfTheGrammar() {
        GrammarPhrases g = grammar();
        assertThat(g.accepts(List.of("turn"))).isFalse();
        assertThat(g.accepts(List.of("go"))).isFalse();
        assertThat(g.accepts(List.of("stop", "stop"))).isFalse();
        assertThat(g.accepts(List.of("turn", "back"))).isFalse();
        assertThat(g.accepts(List.of("<unk>"))).isFalse();
        assertThat(g.accepts(List.of())).isFalse();
    }
}
