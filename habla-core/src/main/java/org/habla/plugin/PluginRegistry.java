package org.habla.plugin;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.ServiceLoader;
import java.util.TreeMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The immutable table of method, driver and bridge types, built once from {@link ServiceLoader}.
 * Two providers with the same name are an error, never a silent override. A provider that cannot be loaded (a
 * class missing from its jar, a constructor that throws, a jar built for a newer Java) is left out and reported in
 * {@link #report()}, with the jar it came from, as is a plugin folder that gave nothing.
 */
public final class PluginRegistry {

    /** How many providers that cannot be loaded are reported before discovery gives up on the rest. */
    static final int MAX_LOAD_FAILURES = 100;
    private static final Logger LOG = LoggerFactory.getLogger(PluginRegistry.class);

    private final Map<String, MethodProvider<?>> methods;
    private final Map<String, DriverProvider<?>> drivers;
    private final Map<String, BridgeProvider<?>> bridges;
    private final PluginReport report;

    private PluginRegistry(Map<String, MethodProvider<?>> methods, Map<String, DriverProvider<?>> drivers,
            Map<String, BridgeProvider<?>> bridges, PluginReport report) {
        this.methods = Collections.unmodifiableMap(methods);
        this.drivers = Collections.unmodifiableMap(drivers);
        this.bridges = Collections.unmodifiableMap(bridges);
        this.report = report;
    }

    /**
     * Discovers every provider visible to {@code loader}; a loader made by {@link PluginJars#open} also tells
     * which jar registered what, and why a jar registered nothing.
     *
     * @throws PluginException if two providers give the same type name
     */
    public static PluginRegistry discover(ClassLoader loader) {
        PluginJars jars = PluginJars.of(loader);
        Map<String, MethodProvider<?>> methods = new TreeMap<>();
        Map<String, DriverProvider<?>> drivers = new TreeMap<>();
        Map<String, BridgeProvider<?>> bridges = new TreeMap<>();
        List<String> duplicates = new ArrayList<>();
        Discovery found = new Discovery(jars);
        for (MethodProvider<?> p : found.load(MethodProvider.class, loader)) {
            found.register("method", p, p::name, methods, duplicates);
        }
        for (DriverProvider<?> p : found.load(DriverProvider.class, loader)) {
            found.register("driver", p, p::name, drivers, duplicates);
        }
        for (BridgeProvider<?> p : found.load(BridgeProvider.class, loader)) {
            found.register("bridge", p, p::name, bridges, duplicates);
        }
        if (!duplicates.isEmpty()) {
            throw new PluginException(String.join("\n", duplicates));
        }
        PluginReport report = found.report();
        report.loaded().forEach(line -> LOG.debug("plugin {}", line));
        report.problems().forEach(line -> LOG.debug("plugin problem: {}", line));
        return new PluginRegistry(methods, drivers, bridges, report);
    }

    /** Discovers the providers on the class path. */
    public static PluginRegistry discover() {
        return discover(PluginRegistry.class.getClassLoader());
    }

    /** A registry of exactly these providers (tests, embedding). Duplicates are an error. */
    public static PluginRegistry of(List<MethodProvider<?>> methodProviders, List<DriverProvider<?>> driverProviders) {
        Map<String, MethodProvider<?>> methods = new TreeMap<>();
        Map<String, DriverProvider<?>> drivers = new TreeMap<>();
        for (MethodProvider<?> p : methodProviders) {
            if (methods.putIfAbsent(p.name(), p) != null) {
                throw new PluginException("method type '" + p.name() + "' is provided twice");
            }
        }
        for (DriverProvider<?> p : driverProviders) {
            if (drivers.putIfAbsent(p.name(), p) != null) {
                throw new PluginException("driver type '" + p.name() + "' is provided twice");
            }
        }
        return new PluginRegistry(methods, drivers, Map.of(), PluginReport.NONE);
    }

    /** Where plugins were looked for, what each jar registered, and what kept a plugin from registering. */
    public PluginReport report() {
        return report;
    }

    public Optional<MethodProvider<?>> method(String name) {
        return Optional.ofNullable(methods.get(name));
    }

    public Optional<DriverProvider<?>> driver(String name) {
        return Optional.ofNullable(drivers.get(name));
    }

    /** Every method type, by name. */
    public Map<String, MethodProvider<?>> methods() {
        return methods;
    }

    public Optional<BridgeProvider<?>> bridge(String name) {
        return Optional.ofNullable(bridges.get(name));
    }

    /** Every bridge type, by name. */
    public Map<String, BridgeProvider<?>> bridges() {
        return bridges;
    }

    /** Every driver type, by name. */
    public Map<String, DriverProvider<?>> drivers() {
        return drivers;
    }

    /** A plugin table that cannot be built. */
    public static final class PluginException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public PluginException(String message) {
            super(message);
        }
    }
}
