package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class GrammarExpansionTest {

    private static Path grammar(String body) throws IOException {
        Path dir = Files.createTempDirectory("habla-grammar");
        Path f = dir.resolve("g.gram");
        Files.writeString(f, "#JSGF V1.0;\ngrammar g;\n" + body);
        f.toFile().deleteOnExit();
        dir.toFile().deleteOnExit();
        return f;
    }

    @Test
    void theBundledGrammarSpellsItsNinePhrases() throws IOException {
        assertThat(GrammarExpansion.phrases(SphinxDecoder.bundledGrammar())).containsExactly("go forward", "turn left",
                "turn right", "go back", "stop", "good dog", "bad dog", "well done", "no");
    }

    @Test
    void optionalPartsRuleReferencesAndTagsAreSpeltOut() throws IOException {
        Path g = grammar("public <cmd> = [please] <move> {tag} | Stop;\n<move> = (go | walk) (left | right);\n");
        assertThat(GrammarExpansion.phrases(g)).containsExactlyInAnyOrder("go left", "walk left", "go right",
                "walk right", "please go left", "please walk left", "please go right", "please walk right", "stop");
    }

    @Test
    void aGrammarWithEndlessPhrasesIsRefusedWithTheReason() throws IOException {
        assertThatThrownBy(() -> GrammarExpansion.phrases(grammar("public <c> = go <d>*;\n<d> = left | right;\n")))
                .hasMessageContaining("endless");
        assertThatThrownBy(() -> GrammarExpansion.phrases(grammar("public <c> = go | go <c>;\n")))
                .hasMessageContaining("endless");
    }

    @Test
    void aGrammarOfTooManyPhrasesIsRefusedNamingTheLimit() throws IOException {
        String digits = "(zero | one | two | three | four | five | six | seven | eight | nine)";
        assertThatThrownBy(() -> GrammarExpansion.phrases(grammar("public <n> = " + digits + " " + digits + " " + digits
                + ";\n"))).hasMessageContaining(String.valueOf(GrammarExpansion.MAX_PHRASES));
    }
}
