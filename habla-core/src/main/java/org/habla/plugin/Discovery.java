package org.habla.plugin;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.function.Supplier;

/**
 * One discovery of providers: loads each kind through {@link ServiceLoader}, goes on past a provider that cannot
 * be loaded (noting it, with the jar that declared it), and remembers which jar registered which type, for the
 * {@link PluginReport}.
 */
final class Discovery {

    private final PluginJars jars;
    private final Map<PluginJar, List<String>> registered = new LinkedHashMap<>();
    private final List<String> failures = new ArrayList<>();
    /** The jars a provider could not be loaded from: their failure already says why they registered nothing. */
    private final java.util.Set<PluginJar> failedJars = new java.util.HashSet<>();

    /** @param jars the plugin jars of the loader, or null for a loader that is not a plugin loader */
    Discovery(PluginJars jars) {
        this.jars = jars;
        if (jars != null) {
            jars.jars().forEach(j -> registered.put(j, new ArrayList<>()));
        }
    }

    /** Every provider of {@code service} that could be made; the others are noted. */
    <S> List<S> load(Class<S> service, ClassLoader loader) {
        List<S> loaded = new ArrayList<>();
        Iterator<S> it = ServiceLoader.load(service, loader).iterator();
        int failed = 0;
        while (failed < PluginRegistry.MAX_LOAD_FAILURES) {
            try {
                if (!it.hasNext()) {
                    break;
                }
                loaded.add(it.next());
            } catch (ServiceConfigurationError | LinkageError e) {
                failed++;
                failures.add(failure(service, e));
            }
        }
        return loaded;
    }

    /**
     * Enters {@code provider} in {@code table} under its name; a name given twice goes to {@code duplicates}, a
     * provider whose name cannot be had (built against another HABLA) to the failures.
     */
    <P> void register(String kind, P provider, Supplier<String> name, Map<String, P> table, List<String> duplicates) {
        String typeName;
        try {
            typeName = name.get();
        } catch (RuntimeException | LinkageError e) {
            failures.add(origin(provider.getClass().getName()) + ": provider " + provider.getClass().getName()
                    + " cannot say its type name: " + e);
            return;
        }
        P old = table.putIfAbsent(typeName, provider);
        if (old != null) {
            duplicates.add(kind + " type '" + typeName + "' is provided twice: by " + old.getClass().getName() + " ("
                    + origin(old.getClass().getName()) + ") and " + provider.getClass().getName() + " ("
                    + origin(provider.getClass().getName()) + ")");
            return;
        }
        PluginJar jar = jarDeclaring(provider.getClass().getName());
        if (jar != null) {
            registered.get(jar).add(kind + " type " + typeName);
        }
    }

    PluginReport report() {
        List<String> loaded = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        if (jars != null) {
            problems.addAll(jars.problems());
            registered.forEach((jar, types) -> {
                problems.addAll(jar.problems());
                if (!types.isEmpty()) {
                    loaded.add(jar.name() + ": " + String.join(", ", types));
                } else if (jar.problems().isEmpty() && !failedJars.contains(jar)) {
                    problems.add(jar.name() + " registers nothing: none of the providers it lists could be loaded");
                }
            });
        }
        problems.addAll(failures);
        String source = jars == null ? "" : jars.source();
        return new PluginReport(source, loaded, problems);
    }

    private String failure(Class<?> service, Throwable e) {
        String message = e.getMessage() == null ? e.toString() : e.getMessage();
        if (message.startsWith(service.getName() + ": ")) {
            message = message.substring(service.getName().length() + 2); // ServiceLoader's prefix: the service
        }
        String cause = e.getCause() == null ? "" : " (" + e.getCause() + ")";
        if (jars != null) {
            for (PluginJar j : jars.jars()) {
                for (String cls : j.declared().getOrDefault(service, List.of())) {
                    if (message.contains(cls) || message.contains(cls.replace('.', '/'))) {
                        failedJars.add(j);
                        return j.name() + ": the provider " + cls + " its META-INF/services/" + service.getName()
                                + " lists cannot be loaded: " + message + cause;
                    }
                }
            }
        }
        return "a " + service.getSimpleName() + " cannot be loaded: " + message + cause;
    }

    private String origin(String className) {
        PluginJar jar = jarDeclaring(className);
        return jar == null ? "built in" : jar.name();
    }

    private PluginJar jarDeclaring(String className) {
        if (jars == null) {
            return null;
        }
        for (PluginJar j : jars.jars()) {
            if (j.declares(className)) {
                return j;
            }
        }
        return null;
    }
}
