package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SphinxDecoderTest {

    @Test
    void sphinxIsGivenTheDictionaryLinesOfTheWordsOfEveryGrammarBesideTheOneItLoads(@TempDir Path dir) throws Exception {
        Path grammar = dir.resolve("robot.gram");
        Files.writeString(grammar, "#JSGF V1.0;\ngrammar robot;\nimport <colours.*>;\npublic <go> = Go Forward | <colours.colour>;\n");
        Files.writeString(dir.resolve("colours.gram"), "#JSGF V1.0;\ngrammar colours;\npublic <colour> = red | read;\n");

        List<String> lines = Files.readAllLines(SphinxDecoder.grammarDictionary(grammar));

        assertThat(lines).extracting(l -> l.substring(0, l.indexOf(' ')).replaceFirst("\\(\\d+\\)$", ""))
                .containsOnly("go", "forward", "red", "read");
        assertThat(lines).contains("go G OW", "forward F AO R W ER D").anyMatch(l -> l.startsWith("read(2) "));
    }
}
