package org.habla;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The engine stays readable file by file: a file over 300 lines says at its top why. */
class SourceSizeTest {

    private static final int MAX_LINES = 300;
    private static final String REASON = "// Over 300 lines, on purpose: ";

    @Test
    void everyEngineFileOver300LinesSaysWhyAtItsTop() throws IOException {
        Path sources = Path.of("src/main/java");
        List<String> unexplained = new ArrayList<>();
        int files = 0;
        try (Stream<Path> walk = Files.walk(sources)) {
            for (Path p : walk.filter(f -> f.toString().endsWith(".java")).toList()) {
                files++;
                List<String> lines = Files.readAllLines(p);
                if (lines.size() > MAX_LINES && !lines.get(0).startsWith(REASON)) {
                    unexplained.add(sources.relativize(p) + " (" + lines.size() + " lines)");
                }
            }
        }
        assertThat(files).as("engine sources found under %s", sources.toAbsolutePath()).isGreaterThan(100);
        assertThat(unexplained).as("files over %d lines without \"%s...\" on their first line", MAX_LINES, REASON)
                .isEmpty();
    }
}
