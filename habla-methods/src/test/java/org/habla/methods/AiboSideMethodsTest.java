package org.habla.methods;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.method.Method;
import org.habla.method.MethodLifecycle;
import org.habla.method.MethodState;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

/** The Aibo-side method types load through the real discovery path and bind their params from a real config. */
class AiboSideMethodsTest {

    private static final List<String> TYPES = List.of("coordinate-translation", "legs", "gait-composition", "buttons",
            "head", "head-control", "camera", "emotion-recognition", "speech", "speaker");

    @Test
    void everyTypeIsFoundByNameWithItsParamsRecord() {
        PluginRegistry registry = PluginRegistry.discover();
        for (String type : TYPES) {
            MethodProvider<?> p = registry.method(type).orElseThrow(() -> new AssertionError("no method type " + type));
            assertThat(p.name()).isEqualTo(type);
            assertThat(p.paramsType().isRecord()).isTrue();
            assertThat(p.description()).isNotBlank();
        }
    }

    @Test
    void theConfigSchemaDescribesEveryParamOfEveryType() {
        String schema = org.habla.config.ConfigSchema.text(PluginRegistry.discover());
        for (String type : TYPES) {
            assertThat(schema).contains("\"" + type + "\"");
        }
        assertThat(schema).contains("touchValence", "strafeShare", "scanPanRad", "targetRadiusM", "maxFps", "volumeDb");
    }

    @Test
    @SuppressWarnings({"unchecked", "rawtypes"})
    void aConfigWiringThemAllLoadsAndEveryMethodIsMadeFromItsParams() throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig config = new ConfigLoader(registry).load(Path.of("src/test/resources/configs/aibo-methods.json"));
        int made = 0;
        for (String type : TYPES) {
            for (MethodConfig mc : config.methods()) {
                if (mc.type().equals(type)) {
                    MethodProvider provider = registry.method(type).orElseThrow();
                    Method m = provider.create(mc.layer(), (Record) mc.params());
                    assertThat(MethodLifecycle.stateOf(m)).isEqualTo(MethodState.NEW);
                    made++;
                }
            }
        }
        assertThat(made).isEqualTo(TYPES.size());
    }
}
