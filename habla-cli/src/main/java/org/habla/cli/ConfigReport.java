package org.habla.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.habla.config.ConfigError;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.method.Layer;

/**
 * What {@code habla check} and {@code habla run} say about a config: every error on a line of its
 * own ({@code $.methods[3].params.x: sentence}), or a one-paragraph summary of a config that is valid.
 * Both commands print errors through here, so a user sees the same lines from either.
 */
final class ConfigReport {

    private static final int WIDTH = 100;

    private ConfigReport() {
    }

    /**
     * Prints a heading naming the file and the count, then one line per error.
     *
     * @param consequence what the error stops, appended to the heading (e.g. "the daemon does not start"),
     *                    or empty
     */
    static void errors(PrintWriter err, Path file, List<ConfigError> errors, String consequence) {
        err.println(file + ": " + errors.size() + (errors.size() == 1 ? " error" : " errors")
                + (consequence.isEmpty() ? "" : "; " + consequence) + ":");
        for (ConfigError e : errors) {
            err.println(line(e));
        }
        err.flush();
    }

    /** One warning line per plugin that could not be loaded or registered nothing. */
    static void pluginProblems(PrintWriter err, org.habla.plugin.PluginReport report) {
        report.problems().forEach(p -> err.println("warning: plugin problem: " + p));
        err.flush();
    }

    /** One error as printed: its JSON path, a colon, the sentence. */
    static String line(ConfigError e) {
        return e.path() + ": " + e.message();
    }

    /** The summary of a valid config: interfaces, methods per layer, control sockets, workers, status. */
    static String summary(Path file, HablaConfig cfg) {
        List<String> parts = new ArrayList<>();
        parts.add(file + " is valid: system '" + cfg.system() + "'");
        parts.add(count(cfg.interfaces().size(), "interface") + list(cfg.interfaces().stream()
                .map(ConfigReport::describe).toList()));
        Map<Layer, Long> perLayer = new EnumMap<>(Layer.class);
        for (Layer l : Layer.values()) {
            perLayer.put(l, cfg.methods().stream().filter(m -> m.layer() == l).count());
        }
        parts.add(count(cfg.methods().size(), "method") + " (" + perLayer.entrySet().stream()
                .map(e -> e.getValue() + " " + e.getKey().configName()).collect(Collectors.joining(", ")) + ")");
        List<String> sockets = cfg.methods().stream().filter(m -> m.expose().isPresent())
                .sorted((a, b) -> Integer.compare(a.expose().get().port(), b.expose().get().port()))
                .map(m -> m.expose().get().name() + " on " + m.expose().get().bind() + ":" + m.expose().get().port()
                        + guard(cfg, m.expose().get()))
                .toList();
        parts.add(count(sockets.size(), "control socket") + list(sockets));
        List<String> remote = cfg.methods().stream().filter(m -> m.host().isPresent())
                .map(m -> m.id() + " on " + m.host().get()).toList();
        if (!remote.isEmpty()) {
            parts.add(count(remote.size(), "method") + " on a worker" + list(remote));
        }
        parts.add(cfg.status().port() == 0 ? "no status endpoint"
                : "status on " + cfg.status().bind() + ":" + cfg.status().port());
        if (cfg.status().monitorPort() > 0) {
            parts.add("monitor on " + cfg.status().monitorBind() + ":" + cfg.status().monitorPort());
        }
        var sec = cfg.security();
        if (sec.credentials() != null) {
            parts.add(count(sec.credentials().clientNames().size(), "client") + " in "
                    + sec.credentialsFile().getFileName() + (sec.credentials().workerSecret().isPresent()
                            ? " with a worker secret" : "") + (sec.auditLog() == null ? ""
                            : "; audit log " + sec.auditLog().getFileName()));
        }
        if (sec.insecure()) {
            parts.add("INSECURE: ports beyond loopback may be open");
        }
        parts.add(cfg.safety().watchdogMs() == 0 ? "motion watchdog on disconnect only"
                : "motion watchdog " + cfg.safety().watchdogMs() + " ms");
        return wrap(String.join("; ", parts) + ".");
    }

    /** How a socket is guarded, where the config says anything about it: " (authenticated, TLS)", " (open)". */
    private static String guard(HablaConfig cfg, org.habla.net.Expose x) {
        if (cfg.security().credentials() == null && !x.tls()) {
            return "";
        }
        return (cfg.security().authenticates(x.bind()) ? " (authenticated" : " (open") + (x.tls() ? ", TLS)" : ")");
    }

    private static String describe(InterfaceConfig i) {
        return i.id() + ": " + i.driver() + " at " + i.address();
    }

    private static String count(long n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    private static String list(List<String> items) {
        return items.isEmpty() ? "" : " (" + String.join(", ", items) + ")";
    }

    /** Breaks a paragraph at spaces so no line is longer than the terminal's usual width. */
    static String wrap(String text) {
        StringBuilder out = new StringBuilder();
        int lineStart = 0;
        for (String word : text.split(" ")) {
            if (out.length() > lineStart && out.length() - lineStart + 1 + word.length() > WIDTH) {
                out.append('\n');
                lineStart = out.length();
            } else if (out.length() > lineStart) {
                out.append(' ');
            }
            out.append(word);
        }
        return out.toString();
    }
}
