package org.habla.plugin;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

/**
 * One plugin jar as found on disk, before anything of it is loaded: the provider classes its services files
 * declare, and what is wrong with it (not a jar, no services file, an empty one).
 *
 * @param path      the jar
 * @param declared  for each HABLA provider interface with a services file in the jar, the classes it lists
 * @param problems  sentences naming the jar and what is wrong; empty when it declares providers
 */
public record PluginJar(Path path, Map<Class<?>, List<String>> declared, List<String> problems) {

    /** The provider interfaces a plugin registers through, each by a services file of its name. */
    static final List<Class<?>> SERVICES = List.of(MethodProvider.class, DriverProvider.class, BridgeProvider.class);
    private static final String SERVICES_FOLDER = "META-INF/services/";

    public PluginJar {
        declared = Collections.unmodifiableMap(new LinkedHashMap<>(declared));
        problems = List.copyOf(problems);
    }

    /** The jar's file name, as reports name it. */
    public String name() {
        return path.getFileName().toString();
    }

    /** Reads the jar's services files; never throws. */
    static PluginJar inspect(Path jar) {
        Map<Class<?>, List<String>> declared = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        String name = jar.getFileName().toString();
        try (JarFile file = new JarFile(jar.toFile())) {
            for (Class<?> service : SERVICES) {
                JarEntry entry = file.getJarEntry(SERVICES_FOLDER + service.getName());
                if (entry != null) {
                    List<String> classes = classes(file, entry);
                    declared.put(service, classes);
                    if (classes.isEmpty()) {
                        problems.add(name + ": its " + entry.getName() + " lists no class");
                    }
                }
            }
            if (declared.isEmpty()) {
                List<String> other = file.stream().map(JarEntry::getName)
                        .filter(n -> n.startsWith(SERVICES_FOLDER) && n.length() > SERVICES_FOLDER.length()).toList();
                problems.add(name + " registers nothing: it has no " + SERVICES_FOLDER + MethodProvider.class.getName()
                        + " (nor ..." + DriverProvider.class.getSimpleName() + ", ..." + BridgeProvider.class.getSimpleName()
                        + ") naming its provider class" + (other.isEmpty() ? "" : "; its services files are " + other));
            }
        } catch (IOException | SecurityException e) {
            problems.add(name + " cannot be read as a jar: " + e.getMessage());
        }
        return new PluginJar(jar, declared, problems);
    }

    /** The class names a services file lists: one per line, {@code #} starts a comment. */
    private static List<String> classes(JarFile file, JarEntry entry) throws IOException {
        List<String> classes = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(file.getInputStream(entry),
                StandardCharsets.UTF_8))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                int hash = line.indexOf('#');
                String cls = (hash >= 0 ? line.substring(0, hash) : line).strip();
                if (!cls.isEmpty()) {
                    classes.add(cls);
                }
            }
        }
        return classes;
    }

    /** Whether this jar's services files list {@code className}. */
    boolean declares(String className) {
        return declared.values().stream().anyMatch(l -> l.contains(className));
    }
}
