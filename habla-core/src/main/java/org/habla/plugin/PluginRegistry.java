package org.habla.plugin;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.TreeMap;

/**
 * The immutable table of method, driver and bridge types, built once from {@link ServiceLoader}.
 * Two providers with the same name are an error, never a silent override.
 */
public final class PluginRegistry {

    private final Map<String, MethodProvider<?>> methods;
    private final Map<String, DriverProvider<?>> drivers;
    private final Map<String, BridgeProvider<?>> bridges;

    private PluginRegistry(Map<String, MethodProvider<?>> methods, Map<String, DriverProvider<?>> drivers,
            Map<String, BridgeProvider<?>> bridges) {
        this.methods = Collections.unmodifiableMap(methods);
        this.drivers = Collections.unmodifiableMap(drivers);
        this.bridges = Collections.unmodifiableMap(bridges);
    }

    /** Discovers every provider visible to {@code loader}. */
    public static PluginRegistry discover(ClassLoader loader) {
        Map<String, MethodProvider<?>> methods = new TreeMap<>();
        Map<String, DriverProvider<?>> drivers = new TreeMap<>();
        Map<String, BridgeProvider<?>> bridges = new TreeMap<>();
        List<String> problems = new ArrayList<>();
        try {
            for (MethodProvider<?> p : ServiceLoader.load(MethodProvider.class, loader)) {
                MethodProvider<?> old = methods.putIfAbsent(p.name(), p);
                if (old != null) {
                    problems.add("method type '" + p.name() + "' is provided twice: by "
                            + old.getClass().getName() + " and " + p.getClass().getName());
                }
            }
            for (DriverProvider<?> p : ServiceLoader.load(DriverProvider.class, loader)) {
                DriverProvider<?> old = drivers.putIfAbsent(p.name(), p);
                if (old != null) {
                    problems.add("driver type '" + p.name() + "' is provided twice: by "
                            + old.getClass().getName() + " and " + p.getClass().getName());
                }
            }
            for (BridgeProvider<?> p : ServiceLoader.load(BridgeProvider.class, loader)) {
                BridgeProvider<?> old = bridges.putIfAbsent(p.name(), p);
                if (old != null) {
                    problems.add("bridge type '" + p.name() + "' is provided twice: by "
                            + old.getClass().getName() + " and " + p.getClass().getName());
                }
            }
        } catch (ServiceConfigurationError e) {
            problems.add("a plugin could not be loaded: " + e.getMessage());
        }
        if (!problems.isEmpty()) {
            throw new PluginException(String.join("\n", problems));
        }
        return new PluginRegistry(methods, drivers, bridges);
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
        return new PluginRegistry(methods, drivers, Map.of());
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
