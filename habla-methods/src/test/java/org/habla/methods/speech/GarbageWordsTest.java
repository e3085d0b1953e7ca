package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The garbage words a grammar gets: its own words alone and their near misses, never their homophones. */
class GarbageWordsTest {

    private static final String GRAMMAR = """
            #JSGF V1.0;
            /* the teacher's words */
            grammar commands;
            public <utterance> = <command> | <reward>;
            <command> = go forward | stop; // moving
            <reward> = /2/ good dog | no {blame};
            """;

    private static final String DICTIONARY = """
            go G OW
            forward F AO R W ER D
            stop S T AA P
            good G UH D
            dog D AO G
            no N OW
            know N OW
            so S OW
            snow S N OW
            ago AH G OW
            stock S T AA K
            stops S T AA P S
            dogs D AO G Z
            dogs(2) D AA G Z
            bird B ER D
            x-ray EH K S R EY
            """;

    @Test
    void grammarWordsAreTheTokensOfTheRuleBodies() {
        assertThat(GarbageWords.grammarWords(GRAMMAR)).containsExactlyInAnyOrder("go", "forward", "stop", "good",
                "dog", "no");
    }

    @Test
    void garbageIsTheGrammarsWordsAndTheirNearMissesButNoHomophone() throws Exception {
        Map<String, List<List<String>>> dict = GarbageWords.readDictionary(
                new ByteArrayInputStream(DICTIONARY.getBytes(StandardCharsets.UTF_8)));
        Map<String, List<String>> garbage = GarbageWords.of(GarbageWords.grammarWords(GRAMMAR), dict);
        assertThat(garbage.keySet()).containsExactlyInAnyOrder("garbage_go", "garbage_forward", "garbage_stop",
                "garbage_good", "garbage_dog", "garbage_no", "garbage_so", "garbage_snow", "garbage_ago",
                "garbage_stock", "garbage_stops", "garbage_dogs");
        assertThat(garbage.get("garbage_stock")).containsExactly("S", "T", "AA", "K");
        assertThat(garbage).doesNotContainKeys("garbage_know", "garbage_bird", "garbage_x-ray");
        assertThat(GarbageWords.isGarbage("garbage_so")).isTrue();
        assertThat(GarbageWords.isGarbage("go")).isFalse();
        assertThat(GarbageWords.addendum(Map.of("garbage_so", List.of("S", "OW")))).isEqualTo("garbage_so S OW\n");
    }

    @Test
    void theGrammarGetsOnePublicRuleOfGarbageWordsWithTheirPrior() {
        String augmented = GarbageWords.augment(GRAMMAR, Set.of("garbage_so", "garbage_stock"), 0.01);
        assertThat(augmented).startsWith(GRAMMAR)
                .contains("public <hablaGarbage> = <hablaGarbageWord>;")
                .contains("/0.0100000/ garbage_so")
                .contains("/0.0100000/ garbage_stock")
                .contains("/0.980000/ <VOID>");
        assertThat(GarbageWords.augment(GRAMMAR, Set.of("garbage_so"), 0)).isEqualTo(GRAMMAR);
    }

    @Test
    void onePhoneApartIsOneSubstitutionInsertionOrDeletion() {
        assertThat(GarbageWords.oneApart(List.of("G", "OW"), List.of("N", "OW"))).isTrue();
        assertThat(GarbageWords.oneApart(List.of("S", "OW"), List.of("S", "N", "OW"))).isTrue();
        assertThat(GarbageWords.oneApart(List.of("S", "T", "AA", "P", "S"), List.of("S", "T", "AA", "P"))).isTrue();
        assertThat(GarbageWords.oneApart(List.of("N", "OW"), List.of("N", "OW"))).isFalse();
        assertThat(GarbageWords.oneApart(List.of("G", "OW"), List.of("S", "N", "OW"))).isFalse();
    }
}
