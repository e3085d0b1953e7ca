package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.habla.net.Limits;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

class ConfigSchemaTest {

    private final PluginRegistry registry = TestPlugins.registry();
    private final ObjectNode schema = ConfigSchema.generate(registry);

    @Test
    void everyKeyTheLoaderAcceptsIsInTheSchemaAndViceVersa() {
        assertThat(ConfigLoader.KEYS_BY_OBJECT).hasSize(12);
        ConfigLoader.KEYS_BY_OBJECT.forEach((where, keys) -> {
            JsonNode object = at(where);
            assertThat(names(object.get("properties"))).as("keys of %s", where).isEqualTo(new TreeSet<>(keys));
            assertThat(object.get("additionalProperties").asBoolean(true)).as("%s is closed", where).isFalse();
        });
    }

    @Test
    void everyFixedObjectOfTheSchemaIsOneTheLoaderKnows() {
        List<String> closed = new ArrayList<>();
        collectClosedObjects(schema, "", closed);
        // the 12 fixed objects, plus one params object per method, driver and bridge type
        assertThat(closed).hasSize(12 + registry.methods().size() + registry.drivers().size()
                + registry.bridges().size());
    }

    @Test
    void paramsOfEachTypeAreDescribedFromTheirRecord() {
        JsonNode sonar = def("params.method.sonar");
        assertThat(names(sonar.get("properties"))).containsExactly("maxRangeM", "minRangeM", "use");
        JsonNode maxRange = sonar.at("/properties/maxRangeM");
        assertThat(maxRange.get("type").asText()).isEqualTo("number");
        assertThat(maxRange.get("default").asDouble()).isEqualTo(5.0);
        assertThat(maxRange.get("x-unit").asText()).isEqualTo("m");
        assertThat(maxRange.get("description").asText()).isEqualTo("Ranges beyond this are reported as this [m]");
        assertThat(sonar.at("/properties/use/items/type").asText()).isEqualTo("integer");
        assertThat(sonar.has("required")).isFalse();

        JsonNode wheels = def("params.method.wheels");
        assertThat(wheels.get("required")).extracting(JsonNode::asText).containsExactly("trackM");
        assertThat(wheels.at("/properties/stop/enum")).extracting(JsonNode::asText).containsExactly("SOFT", "HARD");
        assertThat(wheels.at("/properties/stop/default").asText()).isEqualTo("SOFT");

        assertThat(def("params.method.nearest-distance").get("properties")).isEmpty();
        assertThat(def("params.driver.robot-sim").at("/properties/sonarCount/type").asText()).isEqualTo("integer");
    }

    @Test
    void eachTypeSelectsItsParamsAndLayersWithIfThen() {
        JsonNode cases = def("method").get("allOf");
        assertThat(cases).hasSize(registry.methods().size());
        JsonNode relay = findCase(cases, "type", "relay");
        assertThat(relay.at("/then/properties/params/$ref").asText()).isEqualTo("#/$defs/params.method.relay");
        assertThat(relay.at("/then/properties/layer/enum")).extracting(JsonNode::asText)
                .containsExactly("processing", "virtual");
        JsonNode driver = findCase(def("interface").get("allOf"), "driver", "robot-sim");
        assertThat(driver.at("/then/properties/params/$ref").asText()).isEqualTo("#/$defs/params.driver.robot-sim");
        assertThat(def("method").at("/properties/type/enum")).hasSize(registry.methods().size());
    }

    @Test
    void schemaTextIsDeterministicSortedAndEndsWithANewline() throws Exception {
        String text = ConfigSchema.text(registry);

        assertThat(text).isEqualTo(ConfigSchema.text(registry)).endsWith("}\n").contains("\n  \"$defs\"");
        ObjectMapper json = new ObjectMapper();
        assertThat(json.readTree(text)).isEqualTo(json.readTree(json.writeValueAsString(schema)));
        List<String> defs = new ArrayList<>();
        schema.get("$defs").fieldNames().forEachRemaining(defs::add);
        assertThat(defs).isSorted();
        assertThat(schema.get("$schema").asText()).isEqualTo("https://json-schema.org/draft/2020-12/schema");
    }

    @Test
    void rangesAndDefaultsMatchTheLoader() {
        assertThat(schema.at("/properties/limits/properties/maxLineBytes/default").asInt())
                .isEqualTo(Limits.DEFAULTS.maxLineBytes());
        assertThat(schema.at("/properties/limits/properties/maxLineBytes/maximum").asInt())
                .isEqualTo(ConfigLoader.MAX_LINE_BYTES);
        assertThat(schema.at("/properties/status/properties/port/minimum").asInt()).isZero();
        assertThat(def("method").at("/properties/expose/properties/port/minimum").asInt()).isEqualTo(1);
        assertThat(def("id").get("pattern").asText()).isEqualTo("^" + SourceSyntax.ID.pattern() + "$");
    }

    private JsonNode at(String where) {
        JsonNode node = schema;
        String rest = where.substring(1);
        for (String part : rest.split("\\.")) {
            if (part.isEmpty()) {
                continue;
            }
            boolean element = part.endsWith("[]");
            node = resolve(node.get("properties").get(element ? part.substring(0, part.length() - 2) : part));
            if (element) {
                node = resolve(node.get("items"));
            }
        }
        return node;
    }

    private JsonNode resolve(JsonNode node) {
        return node.has("$ref") ? def(node.get("$ref").asText().substring("#/$defs/".length())) : node;
    }

    private JsonNode def(String name) {
        return schema.get("$defs").get(name);
    }

    private static JsonNode findCase(JsonNode cases, String key, String value) {
        for (JsonNode c : cases) {
            if (c.at("/if/properties/" + key + "/const").asText().equals(value)) {
                return c;
            }
        }
        throw new AssertionError("no case for " + key + " = " + value);
    }

    private static void collectClosedObjects(JsonNode node, String where, List<String> out) {
        if (node.isObject() && node.path("additionalProperties").isBoolean()
                && !node.get("additionalProperties").asBoolean() && node.has("properties")) {
            out.add(where);
        }
        node.properties().forEach(e -> collectClosedObjects(e.getValue(), where + "/" + e.getKey(), out));
        if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                collectClosedObjects(node.get(i), where + "/" + i, out);
            }
        }
    }

    private static Set<String> names(JsonNode object) {
        Set<String> names = new TreeSet<>();
        object.fieldNames().forEachRemaining(names::add);
        return names;
    }
}
