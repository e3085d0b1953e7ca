package org.habla.plugin;

import java.util.List;

/**
 * What a discovery found beyond the built-in types: where plugins were looked for, what each jar registered, and
 * what kept a plugin from registering anything. {@code habla run} logs it at start, {@code habla check} and
 * {@code habla plugins} print it, and a config naming a type that nobody registered gets {@link #why()}.
 *
 * @param source   where plugins were looked for ({@code "--plugins /opt/plugins"}); empty when the registry was
 *                 not discovered from a command line's plugins
 * @param loaded   one line per jar that registered types: {@code "alarm.jar: method type obstacle-alarm"}
 * @param problems one sentence per problem, naming the jar and what is wrong
 */
public record PluginReport(String source, List<String> loaded, List<String> problems) {

    /** The report of a registry made of given providers, not discovered. */
    static final PluginReport NONE = new PluginReport("", List.of(), List.of());

    public PluginReport {
        loaded = List.copyOf(loaded);
        problems = List.copyOf(problems);
    }

    /**
     * One sentence for an error about a type no provider registered: the problems if there are any, else where
     * plugins were looked for and what they registered; empty for a registry not discovered from plugins.
     */
    public String why() {
        if (!problems.isEmpty()) {
            return "plugins: " + String.join("; ", problems);
        }
        if (source.isEmpty()) {
            return "";
        }
        return "plugins: " + source + (loaded.isEmpty() ? "" : ", loaded " + String.join("; ", loaded));
    }

    /** Says at start where plugins came from and what each jar registered (INFO), and every problem (WARN). */
    public void logTo(org.slf4j.Logger log) {
        if (source.isEmpty() && problems.isEmpty()) {
            return;
        }
        log.info("plugins: {}{}", source, loaded.isEmpty() ? "" : ": " + String.join("; ", loaded));
        problems.forEach(p -> log.warn("plugin problem: {}", p));
    }
}
