package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

/**
 * The committed {@code config/habla-config.schema.json} is the schema of the whole plugin set: this
 * module sees every method and driver type, so a type added, renamed or given a new parameter without
 * regenerating the file fails here.
 */
class SchemaFileTest {

    private static final String REGENERATE = "run ./habla schema --output config/habla-config.schema.json";

    @Test
    void committedSchemaMatchesTheRegisteredTypes() throws IOException {
        Path file = projectRoot().resolve("config/habla-config.schema.json");
        assertThat(file).as("the committed schema is missing; " + REGENERATE).exists();

        String generated = ConfigSchema.text(PluginRegistry.discover());

        assertThat(Files.readString(file))
                .as("config/habla-config.schema.json is out of date; " + REGENERATE)
                .isEqualTo(generated);
    }

    /** The folder holding the parent pom and {@code config/}, found from the module's working folder. */
    private static Path projectRoot() {
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.isDirectory(dir.resolve("habla-core"))) {
            dir = dir.getParent();
        }
        assertThat(dir).as("no project root above " + Path.of("").toAbsolutePath()).isNotNull();
        return dir;
    }
}
