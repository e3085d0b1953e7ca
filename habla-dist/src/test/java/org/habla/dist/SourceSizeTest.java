package org.habla.dist;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** Every module stays readable file by file: a main source file over 300 lines says at its top why. */
class SourceSizeTest {

    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
    private static final int MAX_LINES = 300;
    private static final String REASON = "// Over 300 lines, on purpose: ";
    /** How deep a module's {@code src/main/java} lies at most ({@code examples/custom-method/src/main/java}). */
    private static final int MODULE_DEPTH = 5;

    @Test
    void everyMainFileOver300LinesSaysWhyAtItsTop() throws IOException {
        List<String> unexplained = new ArrayList<>();
        List<Path> modules = new ArrayList<>();
        for (Path sources : mainSourceFolders()) {
            modules.add(ROOT.relativize(sources));
            try (Stream<Path> walk = Files.walk(sources)) {
                for (Path p : walk.filter(f -> f.toString().endsWith(".java")).toList()) {
                    List<String> lines = Files.readAllLines(p);
                    if (lines.size() > MAX_LINES && !lines.get(0).startsWith(REASON)) {
                        unexplained.add(ROOT.relativize(p) + " (" + lines.size() + " lines)");
                    }
                }
            }
        }
        assertThat(modules).as("the modules' main sources under %s", ROOT)
                .contains(Path.of("habla-core/src/main/java"), Path.of("habla-cli/src/main/java"),
                        Path.of("habla-methods/src/main/java"), Path.of("examples/custom-method/src/main/java"));
        assertThat(unexplained).as("files over %d lines without \"%s...\" on their first line", MAX_LINES, REASON)
                .isEmpty();
    }

    /** Every {@code src/main/java} of the repository: each module's, the examples'. */
    private static List<Path> mainSourceFolders() throws IOException {
        try (Stream<Path> found = Files.find(ROOT, MODULE_DEPTH, (p, attributes) -> attributes.isDirectory()
                && p.endsWith(Path.of("src", "main", "java")) && !p.toString().contains("/target/"))) {
            return found.sorted().toList();
        }
    }
}
