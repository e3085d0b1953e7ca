package org.habla.plugin;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.config.ParamsJson;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Builds {@code examples/custom-method} the way a method author would (compile against habla-core,
 * jar it with its services file), drops the jar in a plugins folder and loads it by type name.
 */
class CustomMethodExampleTest {

    @Test
    void theExamplePluginBuildsLoadsByNameAndRuns(@TempDir Path tmp) throws Exception {
        Path jar = buildExampleJar(tmp);
        try (URLClassLoader loader = new URLClassLoader(new URL[] {jar.toUri().toURL()},
                CustomMethodExampleTest.class.getClassLoader())) {
            PluginRegistry registry = PluginRegistry.discover(loader);
            assertThat(registry.method("threshold")).isPresent();
            @SuppressWarnings("unchecked")
            MethodProvider<Record> provider = (MethodProvider<Record>) registry.method("threshold").orElseThrow();
            assertThat(provider.layers()).containsExactly(Layer.PROCESSING);
            Record params = ParamsJson.defaults(provider.paramsType());
            assertThat(provider.ports(Layer.PROCESSING, params).inputs()).extracting(InputPort::name)
                    .containsExactly("nearest");
            Method m = MethodProvider.make(provider, Layer.PROCESSING, params);
            MethodHarness h = MethodHarness.started("near", m);
            for (double distanceM : new double[] {1.0, 0.7, 0.4, 0.6, 0.9}) {
                h.push("nearest", RecordValue.builder().put("distanceM", distanceM).build());
            }
            assertThat(h.values("label")).containsExactly(new TextValue("far"), new TextValue("near"),
                    new TextValue("far"));
        }
    }

    /** The example built as its author would, in a plugins folder. */
    static Path buildExampleJar(Path tmp) throws IOException {
        return ExamplePlugin.jar(tmp, Files.createDirectories(tmp.resolve("plugins")).resolve("threshold-method.jar"));
    }
}
