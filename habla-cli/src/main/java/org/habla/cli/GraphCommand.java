package org.habla.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.draw.DrawingFormat;
import org.habla.draw.GraphPicture;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla graph CONFIG}: draws the config's three-layer graph — interfaces below, the sensors &amp;
 * actuators, processing and virtual bands, the control sockets with their ports above; sensing arrows
 * up, actuation arrows down — as Graphviz dot, Mermaid or SVG. A bad config is refused with the same
 * lines as {@code habla check}.
 */
@Command(name = "graph", mixinStandardHelpOptions = true,
        description = "Draw a config's three-layer method graph as dot, mermaid or svg.")
public final class GraphCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CONFIG", description = "The JSON config file.")
    private Path config;

    @Option(names = {"-f", "--format"}, paramLabel = "FORMAT",
            description = "dot, mermaid or svg; default: from the --output file's extension (.dot/.gv, .mmd, .svg), else dot.")
    private String format;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE", description = "Write to FILE instead of printing.")
    private Path output;

    private final PluginRegistry registry;

    public GraphCommand() {
        this(null);
    }

    /** A drawing with exactly these plugins instead of the ones on the class path. */
    public GraphCommand(PluginRegistry registry) {
        this.registry = registry;
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        DrawingFormat f;
        if (format != null) {
            try {
                f = DrawingFormat.valueOf(format.toUpperCase(java.util.Locale.ROOT));
            } catch (IllegalArgumentException e) {
                err.println("habla graph: unknown format '" + format + "' (expected dot, mermaid or svg)");
                err.flush();
                return ExitCodes.USAGE_OR_CONFIG;
            }
        } else {
            f = output == null ? DrawingFormat.DOT : DrawingFormat.ofFileName(output).orElse(DrawingFormat.DOT);
        }
        PluginRegistry r = registry != null ? registry : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        HablaConfig cfg;
        try {
            cfg = new ConfigLoader(r).load(config);
        } catch (ConfigException e) {
            ConfigReport.errors(err, config, e.errors(), "nothing is drawn");
            return ExitCodes.USAGE_OR_CONFIG;
        }
        String text = f.write(GraphPicture.of(cfg, r));
        if (!CommandOutput.put(spec, output, text)) {
            return ExitCodes.RUNTIME_FAILURE;
        }
        return ExitCodes.OK;
    }
}
