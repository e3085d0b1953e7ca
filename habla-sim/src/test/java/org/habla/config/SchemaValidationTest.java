package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SchemaId;
import com.networknt.schema.SchemaLocation;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The committed {@code config/habla-config.schema.json}, checked by an independent JSON Schema validator
 * (draft 2020-12): the schema itself follows its metaschema, every config in {@code config/} follows the
 * schema, and broken configs are refused at the place they break.
 */
class SchemaValidationTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final JsonSchemaFactory FACTORY = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012);

    @Test
    void theSchemaFollowsTheDraft2020MetaSchema() throws IOException {
        JsonSchema meta = FACTORY.getSchema(SchemaLocation.of(SchemaId.V202012));

        assertThat(meta.validate(read(configDir().resolve("habla-config.schema.json")))).isEmpty();
    }

    @Test
    void theMetaSchemaRefusesASchemaWithAWrongType() throws IOException {
        JsonSchema meta = FACTORY.getSchema(SchemaLocation.of(SchemaId.V202012));
        ObjectNode broken = (ObjectNode) read(configDir().resolve("habla-config.schema.json"));
        broken.put("type", 5);

        assertThat(meta.validate(broken)).isNotEmpty();
    }

    @Test
    void everyDefaultFollowsItsOwnPropertysSchema() throws IOException {
        Path file = configDir().resolve("habla-config.schema.json");
        List<String> pointers = new ArrayList<>();
        defaults(read(file), "", pointers);
        assertThat(pointers).hasSizeGreaterThan(200);

        for (String pointer : pointers) {
            JsonSchema property = FACTORY.getSchema(SchemaLocation.of(file.toUri() + "#" + pointer));
            JsonNode value = read(file).at(pointer + "/default");
            assertThat(property.validate(value)).as("default %s at %s", value, pointer).isEmpty();
        }
    }

    static Stream<String> configs() throws IOException {
        try (Stream<Path> files = Files.list(configDir())) {
            List<String> names = files.map(f -> f.getFileName().toString())
                    .filter(n -> n.endsWith(".json") && !n.equals("habla-config.schema.json"))
                    .sorted().toList();
            assertThat(names).contains("pioneer.json", "aibo.json", "room.json");
            return names.stream();
        }
    }

    @ParameterizedTest(name = "config/{0}")
    @MethodSource("configs")
    void everyConfigFollowsTheSchema(String file) throws IOException {
        assertThat(schema().validate(read(configDir().resolve(file)))).isEmpty();
    }

    @Test
    void anUnknownTopLevelKeyIsRefused() throws IOException {
        assertRefusedAt("$.colour", c -> c.put("colour", "blue"));
    }

    @Test
    void anUnknownMethodTypeIsRefused() throws IOException {
        assertRefusedAt("$.methods[0].type", c -> method(c, 0).put("type", "no-such-method"));
    }

    @Test
    void anUnknownParameterIsRefused() throws IOException {
        assertRefusedAt("$.methods[0].params", c -> method(c, 0).putObject("params").put("maxRangeMetres", 5));
    }

    @Test
    void aNumberGivenAsTextIsRefused() throws IOException {
        // methods[0] of the Pioneer's config is its sonar
        assertRefusedAt("$.methods[0].params.maxRangeM", c -> method(c, 0).putObject("params").put("maxRangeM", "5"));
    }

    @Test
    void anIntegerParameterGivenAFractionIsRefused() throws IOException {
        // methods[2] is the keyboard, whose maxLength counts characters
        assertRefusedAt("$.methods[2].params.maxLength", c -> method(c, 2).putObject("params").put("maxLength", 2.5));
    }

    /** The Pioneer's config, broken by {@code breakIt}, gives an error at {@code path} (or under it). */
    private static void assertRefusedAt(String path, Consumer<ObjectNode> breakIt) throws IOException {
        ObjectNode config = (ObjectNode) read(configDir().resolve("pioneer.json"));
        assertThat(schema().validate(config)).as("the unbroken config").isEmpty();
        breakIt.accept(config);

        Set<ValidationMessage> errors = schema().validate(config);

        assertThat(errors).as("errors of the broken config")
                .anySatisfy(e -> assertThat(e.getInstanceLocation().toString() + "." + e.getProperty()).startsWith(path));
    }

    /** The JSON pointer of every subschema under {@code node} that states a default. */
    private static void defaults(JsonNode node, String pointer, List<String> found) {
        if (node.isObject() && node.has("default") && node.has("type")) {
            found.add(pointer);
        }
        if (node.isContainerNode()) {
            var fields = node.isObject() ? node.fieldNames() : null;
            if (fields != null) {
                fields.forEachRemaining(k -> defaults(node.get(k), pointer + "/" + k.replace("~", "~0").replace("/", "~1"), found));
            } else {
                for (int i = 0; i < node.size(); i++) {
                    defaults(node.get(i), pointer + "/" + i, found);
                }
            }
        }
    }

    private static ObjectNode method(ObjectNode config, int index) {
        return (ObjectNode) config.withArray("/methods").get(index);
    }

    /** The schema, read from its file: its relative {@code $id} resolves against the file's location. */
    private static JsonSchema schema() throws IOException {
        Path file = configDir().resolve("habla-config.schema.json");
        return FACTORY.getSchema(SchemaLocation.of(file.toUri().toString()), read(file));
    }

    private static JsonNode read(Path file) throws IOException {
        return JSON.readTree(file.toFile());
    }

    /** The project's {@code config/}, found from the module's working folder. */
    private static Path configDir() {
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.isDirectory(dir.resolve("habla-core"))) {
            dir = dir.getParent();
        }
        assertThat(dir).as("no project root above " + Path.of("").toAbsolutePath()).isNotNull();
        return dir.resolve("config");
    }
}
