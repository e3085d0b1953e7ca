package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A method placed on a worker gets its params as JSON written from the daemon's bound record; the worker
 * binds them again. For every method of the robots' configs, that round trip must give the same settings.
 */
class PlacedParamsTest {

    @ParameterizedTest(name = "config/{0}")
    @ValueSource(strings = {"pioneer.json", "aibo.json"})
    void everyMethodsParamsSurviveTheTripToAWorker(String file) throws Exception {
        Path root = Path.of("").toAbsolutePath();
        while (!Files.isDirectory(root.resolve("habla-core"))) {
            root = root.getParent();
        }
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig config = new ConfigLoader(registry).load(root.resolve("config").resolve(file));
        assertThat(config.methods()).isNotEmpty();
        for (MethodConfig mc : config.methods()) {
            ObjectNode sent = ParamsJson.write(mc.params());
            Record bound = ParamsJson.read(sent, registry.method(mc.type()).orElseThrow().paramsType());
            assertThat(ParamsJson.write(bound)).as("params of %s (%s)", mc.id(), mc.type()).isEqualTo(sent);
            assertThat(bound.getClass()).isEqualTo(mc.params().getClass());
        }
    }
}
