package org.habla.plugin;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
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

    private static final Path EXAMPLE = Paths.get("..", "examples", "custom-method").toAbsolutePath().normalize();

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

    /** Compiles the example against the test class path and jars it with its resources. */
    static Path buildExampleJar(Path tmp) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertThat(javac).as("a JDK compiler").isNotNull();
        Path classes = Files.createDirectories(tmp.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-d", classes.toString(), "--release", "21",
                "-cp", System.getProperty("java.class.path")));
        try (Stream<Path> files = Files.walk(EXAMPLE.resolve("src/main/java"))) {
            files.filter(p -> p.toString().endsWith(".java")).forEach(p -> args.add(p.toString()));
        }
        int rc = javac.run(null, null, null, args.toArray(String[]::new));
        assertThat(rc).as("javac exit code").isZero();
        Path jar = Files.createDirectories(tmp.resolve("plugins")).resolve("threshold-method.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            add(out, classes);
            add(out, EXAMPLE.resolve("src/main/resources"));
        }
        return jar;
    }

    private static void add(JarOutputStream out, Path base) throws IOException {
        try (Stream<Path> files = Files.walk(base)) {
            for (Path p : files.filter(Files::isRegularFile).sorted().toList()) {
                out.putNextEntry(new JarEntry(base.relativize(p).toString().replace('\\', '/')));
                try (var in = Files.newInputStream(p)) {
                    in.transferTo((OutputStream) out);
                }
                out.closeEntry();
            }
        }
    }
}
