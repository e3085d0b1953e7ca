package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;

/**
 * The Moonshine model for the tests that run it: the cache folder {@code ./habla models fetch} fills. A test
 * that needs it and finds it missing fails with the command that fetches it, never skips.
 */
final class MoonshineModelFolder {

    private MoonshineModelFolder() {
    }

    static Path required() {
        Path folder = MoonshineFiles.defaultFolder();
        assertThat(MoonshineFiles.missing(folder)).as("the Moonshine model for this test").isEmpty();
        return folder;
    }
}
