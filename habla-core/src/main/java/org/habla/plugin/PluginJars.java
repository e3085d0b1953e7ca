package org.habla.plugin;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.stream.Stream;

/**
 * The plugin jars a command line names: the folder (or the one jar) given with {@code --plugins}, else a
 * {@code plugins} folder in the working directory if there is one, opened as one class loader over the
 * application's. What it found is kept with the loader ({@link #loader()}), so that the
 * {@link PluginRegistry} discovered from it can say which jar registered which type and, when a config names a
 * type nobody registered, why a plugin gave nothing: the folder is missing or empty, or a jar has no services file.
 *
 * <pre>
 *   --plugins DIR   every *.jar in DIR (not its sub-folders)
 *   --plugins JAR   that one jar
 *   (none)          every *.jar in ./plugins, if that folder exists; else the built-in types only
 * </pre>
 */
public final class PluginJars {

    /** The folder looked in when {@code --plugins} is not given, relative to the working directory. */
    public static final Path DEFAULT_FOLDER = Path.of("plugins");

    private final String source;
    private final List<PluginJar> jars;
    private final List<String> problems;
    private final ClassLoader loader;

    private PluginJars(String source, List<PluginJar> jars, List<String> problems, ClassLoader parent) {
        this.source = source;
        this.jars = List.copyOf(jars);
        this.problems = List.copyOf(problems);
        this.loader = new Loader(urls(jars), parent, this); // even with no jar: it carries the report
    }

    /**
     * Opens the plugins named by {@code --plugins} ({@code named}, or null when the option was not given) as a
     * class loader over {@code parent}. Never throws: what cannot be read becomes a problem in the report.
     */
    public static PluginJars open(Path named, ClassLoader parent) {
        Objects.requireNonNull(parent, "parent");
        if (named == null) {
            if (!Files.isDirectory(DEFAULT_FOLDER)) {
                return new PluginJars("no plugins folder (" + DEFAULT_FOLDER.toAbsolutePath()
                        + " does not exist and --plugins was not given)", List.of(), List.of(), parent);
            }
            return folder(DEFAULT_FOLDER, "the plugins folder " + DEFAULT_FOLDER.toAbsolutePath(), parent);
        }
        Path abs = named.toAbsolutePath().normalize();
        if (Files.isDirectory(named)) {
            return folder(named, "--plugins " + abs, parent);
        }
        if (Files.isRegularFile(named) && isJar(named)) {
            return new PluginJars("--plugins " + abs + " (one jar)", List.of(PluginJar.inspect(named)), List.of(),
                    parent);
        }
        String why = Files.exists(named) ? "is neither a folder nor a .jar file" : "does not exist";
        return new PluginJars("--plugins " + abs, List.of(), List.of("--plugins " + abs + " " + why
                + ": give a folder of plugin jars, or one jar"), parent);
    }

    /** The plugins a class loader was opened with, or none if it is not one of {@link #loader()}'s. */
    static PluginJars of(ClassLoader loader) {
        return loader instanceof Loader l ? l.jars : null;
    }

    private static PluginJars folder(Path dir, String source, ClassLoader parent) {
        List<Path> found;
        try (Stream<Path> files = Files.list(dir)) {
            found = files.filter(f -> Files.isRegularFile(f) && isJar(f)).sorted().toList();
        } catch (IOException e) {
            return new PluginJars(source, List.of(), List.of("cannot read " + source + ": " + e.getMessage()), parent);
        }
        if (found.isEmpty()) {
            return new PluginJars(source, List.of(), List.of(source + " has no .jar file"), parent);
        }
        return new PluginJars(source, found.stream().map(PluginJar::inspect).toList(), List.of(), parent);
    }

    private static boolean isJar(Path p) {
        return p.getFileName().toString().endsWith(".jar");
    }

    private static URL[] urls(List<PluginJar> jars) {
        List<URL> urls = new ArrayList<>();
        for (PluginJar j : jars) {
            try {
                urls.add(j.path().toUri().toURL());
            } catch (MalformedURLException e) {
                throw new IllegalStateException("a file path is not a URL: " + j.path(), e);
            }
        }
        return urls.toArray(URL[]::new);
    }

    /** The class loader over the jars (over none, if none was found), delegating to the application's first. */
    public ClassLoader loader() {
        return loader;
    }

    /** Where the plugins were looked for, as a sentence ({@code "--plugins /opt/habla/plugins"}). */
    public String source() {
        return source;
    }

    /** Every jar found, in name order, with what its services files declare. */
    public List<PluginJar> jars() {
        return jars;
    }

    /** What keeps plugins from being loaded at all (a missing or empty folder); a jar's own problems are its. */
    public List<String> problems() {
        return problems;
    }

    /** The class loader over the plugin jars, carrying what was found. */
    private static final class Loader extends URLClassLoader {
        static {
            registerAsParallelCapable();
        }

        private final PluginJars jars;

        Loader(URL[] urls, ClassLoader parent, PluginJars jars) {
            super("habla-plugins", urls, parent);
            this.jars = jars;
        }
    }
}
