package org.habla.testing;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The test configs of habla-core ({@code src/test/resources/configs}) as files, for the tests of every module: as a
 * resource of the core test jar a config is no file, and a test that lists a folder of them needs one. A module's
 * tests run in the module's folder, beside habla-core's.
 */
public final class TestConfigs {

    private static final Path FOLDER = Path.of("..", "habla-core", "src", "test", "resources", "configs");

    private TestConfigs() {
    }

    /** The config (or folder of configs) {@code name}, e.g. {@code valid/pioneer-like.json}. */
    public static Path file(String name) {
        Path p = FOLDER.resolve(name).toAbsolutePath().normalize();
        if (!Files.exists(p)) {
            throw new IllegalArgumentException("no test config " + p);
        }
        return p;
    }
}
