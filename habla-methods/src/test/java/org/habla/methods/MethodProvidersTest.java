package org.habla.methods;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.config.ParamsJson;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Ports;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

/** Every provider this library lists is found through the real discovery path, under a name of its own. */
class MethodProvidersTest {

    private static final String SERVICES = "META-INF/services/org.habla.plugin.MethodProvider";

    private static List<String> listedProviders() throws Exception {
        List<String> names = new ArrayList<>();
        try (InputStream in = MethodProvidersTest.class.getClassLoader().getResourceAsStream(SERVICES)) {
            assertThat(in).as(SERVICES + " is on the class path").isNotNull();
            BufferedReader r = new BufferedReader(new InputStreamReader(in, UTF_8));
            for (String line; (line = r.readLine()) != null; ) {
                String name = line.strip();
                if (!name.isEmpty() && !name.startsWith("#")) {
                    names.add(name);
                }
            }
        }
        return names;
    }

    @Test
    void everyListedProviderLoadsUnderAUniqueName() throws Exception {
        List<String> listed = listedProviders();
        assertThat(listed).doesNotHaveDuplicates();
        PluginRegistry registry = PluginRegistry.discover();
        Map<String, String> typeByClass = registry.methods().values().stream()
                .collect(Collectors.toMap(p -> p.getClass().getName(), MethodProvider::name));
        Set<String> names = new HashSet<>();
        for (String className : listed) {
            assertThat(typeByClass).as("discovered: " + className).containsKey(className);
            assertThat(names.add(typeByClass.get(className))).as("unique type name " + typeByClass.get(className)).isTrue();
        }
        assertThat(names).contains("sonar", "infrared", "laser", "microphone", "keyboard", "odometry", "wheels",
                "nearest-distance", "motion-composition", "movement-safety", "distance-angle", "command", "reward",
                "action", "robot-pose", "link-state");
    }

    @Test
    void everyTypeWithoutRequiredParamsMakesAMethodOfItsLayerThatBindsTheListedPortsFromAnEmptyParamsObject()
            throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        int made = 0;
        for (String className : listedProviders()) {
            MethodProvider<?> provider = registry.methods().values().stream()
                    .filter(p -> p.getClass().getName().equals(className)).findFirst().orElseThrow();
            Record params;
            try {
                params = ParamsJson.defaults(provider.paramsType());
            } catch (Exception e) {
                continue; // a type with a required parameter
            }
            for (Layer layer : provider.layers()) {
                Method m = MethodProvider.make(provider, layer, params); // refuses other ports than the listed ones
                assertThat(m.layer()).isEqualTo(layer);
                assertThat(m.outputs().size() + m.inputs().size()).as(provider.name() + " has ports").isPositive();
                assertThat(ports(provider, layer, params).differences(m.boundPorts())).as(provider.name()).isEmpty();
                made++;
            }
        }
        assertThat(made).isGreaterThanOrEqualTo(15);
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Ports ports(MethodProvider provider, Layer layer, Record params) {
        return provider.ports(layer, params);
    }
}
