package org.habla.plugin;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
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

/**
 * Builds {@code examples/custom-method} the way a method author would (compile against habla-core, jar the classes
 * with a services file), or with the mistakes an author makes: no services file, or one naming a class the jar
 * lacks.
 */
public final class ExamplePlugin {

    static final Path EXAMPLE = Paths.get("..", "examples", "custom-method").toAbsolutePath().normalize();
    /** The services file the example ships. */
    public static final String SERVICES = "META-INF/services/" + MethodProvider.class.getName();

    private ExamplePlugin() {
    }

    /** The example as its build makes it: classes and resources, services file included. */
    public static Path jar(Path tmp, Path jar) throws IOException {
        Path classes = compile(tmp);
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            add(out, classes);
            add(out, EXAMPLE.resolve("src/main/resources"));
        }
        return jar;
    }

    /** The example's classes with {@code services} as its services file, or with none if it is null. */
    public static Path jarWithServices(Path tmp, Path jar, String services) throws IOException {
        Path classes = compile(tmp);
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            add(out, classes);
            if (services != null) {
                out.putNextEntry(new JarEntry(SERVICES));
                out.write(services.getBytes(StandardCharsets.UTF_8));
                out.closeEntry();
            }
        }
        return jar;
    }

    /** Compiles the example against the test class path, once per {@code tmp}. */
    private static Path compile(Path tmp) throws IOException {
        Path classes = tmp.resolve("example-classes");
        if (Files.isDirectory(classes)) {
            return classes;
        }
        Files.createDirectories(classes);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertThat(javac).as("a JDK compiler").isNotNull();
        List<String> args = new ArrayList<>(List.of("-d", classes.toString(), "--release", "21",
                "-cp", System.getProperty("java.class.path")));
        try (Stream<Path> files = Files.walk(EXAMPLE.resolve("src/main/java"))) {
            files.filter(p -> p.toString().endsWith(".java")).forEach(p -> args.add(p.toString()));
        }
        int rc = javac.run(null, null, null, args.toArray(String[]::new));
        assertThat(rc).as("javac exit code").isZero();
        return classes;
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
