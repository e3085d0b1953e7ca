package org.habla.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigSchema;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code habla schema [--output FILE]}: the JSON Schema of config files for every method and driver
 * type on the class path (plugins included), so an editor can complete and check a config as it is
 * typed. The text depends only on the plugin set: keys and types are sorted.
 */
@Command(name = "schema", mixinStandardHelpOptions = true,
        description = "Print (or write) the JSON Schema of HABLA configs for every registered method and driver type.")
public final class SchemaCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE",
            description = "Write the schema to FILE (folders are made) instead of printing it.")
    private Path output;

    private final PluginRegistry registry;

    public SchemaCommand() {
        this(null);
    }

    /** The schema of exactly these plugins instead of the ones on the class path. */
    public SchemaCommand(PluginRegistry registry) {
        this.registry = registry;
    }

    @Override
    public Integer call() {
        PluginRegistry r = registry != null ? registry : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        String schema = ConfigSchema.text(r);
        if (!CommandOutput.put(spec, output, schema)) {
            return ExitCodes.RUNTIME_FAILURE;
        }
        if (output == null) {
            return ExitCodes.OK;
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println("wrote " + output + " (" + r.methods().size() + " method types, " + r.drivers().size()
                + " driver types)");
        out.flush();
        return ExitCodes.OK;
    }
}
