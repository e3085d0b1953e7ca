package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
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

    @Test
    void decodingLogsNothingBelowWarningEvenAfterTheLoggersSphinxConfiguredWereCollected() throws Exception {
        SphinxDecoder decoder = SphinxDecoder.load(SpeechRecognition.settings(SpeechRecognitionParams.defaults()),
                Optional.empty());
        System.gc(); // the logging system holds loggers weakly: this is when Sphinx's own level setting was lost
        List<LogRecord> seen = new ArrayList<>();
        Handler spy = new Handler() {
            @Override
            public synchronized void publish(LogRecord r) {
                seen.add(r);
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger root = Logger.getLogger("");
        root.addHandler(spy);
        try {
            decoder.decode(Utterances.all().getFirst().audio());
        } finally {
            root.removeHandler(spy);
        }

        synchronized (spy) {
            assertThat(seen).filteredOn(r -> r.getLevel().intValue() < Level.WARNING.intValue())
                    .extracting(r -> r.getSourceClassName() + ": " + r.getMessage())
                    .noneMatch(m -> m.startsWith("edu.cmu.sphinx"));
        }
    }
}
