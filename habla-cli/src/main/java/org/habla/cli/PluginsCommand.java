package org.habla.cli;

import java.io.PrintWriter;
import java.lang.reflect.RecordComponent;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.habla.command.ExitCodes;
import org.habla.config.ParamsJson;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.Param;
import org.habla.plugin.ParamRange;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.RecordField;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code habla plugins}: every method and driver type on the class path, with layers ("light" after them for a
 * type whose methods may run on the thread that feeds them) and parameters, and each method type's ports as its
 * provider lists them for the default parameters (no method is made), a record output with its declared fields.
 */
@Command(name = "plugins", mixinStandardHelpOptions = true,
        description = "List every method type and driver type, with its layers, parameters and ports.")
public final class PluginsCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    private final PluginRegistry registry;

    public PluginsCommand() {
        this(null);
    }

    public PluginsCommand(PluginRegistry registry) {
        this.registry = registry;
    }

    @Override
    public Integer call() {
        PluginRegistry r = registry != null ? registry : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        PrintWriter out = spec.commandLine().getOut();
        out.println("Method types (" + r.methods().size() + "):");
        for (Map.Entry<String, MethodProvider<?>> e : r.methods().entrySet()) {
            MethodProvider<?> p = e.getValue();
            String layers = p.layers().stream().sorted().map(Layer::configName).collect(Collectors.joining(", "));
            String light = p.light() ? " light" : "";
            out.println("  " + e.getKey() + "  [" + layers + "]" + light + "  " + p.description());
            printParams(out, p.paramsType());
            printPorts(out, p);
        }
        out.println();
        out.println("Driver types (" + r.drivers().size() + "):");
        for (Map.Entry<String, DriverProvider<?>> e : r.drivers().entrySet()) {
            out.println("  " + e.getKey() + "  " + e.getValue().description());
            printParams(out, e.getValue().paramsType());
        }
        out.println();
        out.println("Bridge types (" + r.bridges().size() + "):");
        for (Map.Entry<String, org.habla.plugin.BridgeProvider<?>> e : r.bridges().entrySet()) {
            out.println("  " + e.getKey() + "  " + e.getValue().description());
            printParams(out, e.getValue().paramsType());
        }
        if (!r.report().source().isEmpty()) {
            out.println();
            out.println("Plugins: " + r.report().source());
            r.report().loaded().forEach(line -> out.println("  " + line));
        }
        out.flush();
        ConfigReport.pluginProblems(spec.commandLine().getErr(), r.report());
        return ExitCodes.OK;
    }

    /** The ports for the default params; a type with required params says its ports wait for them. */
    private static <P extends Record> void printPorts(PrintWriter out, MethodProvider<P> provider) {
        Ports ports;
        try {
            P defaults = ParamsJson.defaults(provider.paramsType());
            ports = provider.ports(provider.layers().stream().sorted().findFirst().orElseThrow(), defaults);
        } catch (RuntimeException e) {
            out.println("      ports: as its parameters say (the defaults alone do not make a method of it)");
            return;
        }
        for (InputPort<?> in : ports.inputs()) {
            out.println("      " + in);
        }
        for (OutputPort<?> o : ports.outputs()) {
            String unit = o.shape().unit().isEmpty() ? "" : " [" + o.shape().unit() + "]";
            String doc = o.shape().doc().isEmpty() ? "" : "  " + o.shape().doc();
            out.println("      " + o + unit + doc);
            for (RecordField f : o.shape().recordFields()) {
                out.println("          " + f);
            }
        }
    }

    private static void printParams(PrintWriter out, Class<? extends Record> params) {
        for (RecordComponent c : params.getRecordComponents()) {
            Param doc = c.getAnnotation(Param.class);
            StringBuilder line = new StringBuilder("      ").append(c.getName()).append(": ")
                    .append(c.getGenericType().getTypeName().replaceAll("[a-z]+\\.", ""));
            if (doc != null) {
                if (!doc.unit().isEmpty()) {
                    line.append(" [").append(doc.unit()).append(']');
                }
                if (!doc.defaultValue().isEmpty()) {
                    line.append(" = ").append(doc.defaultValue());
                } else if (!doc.defaultNote().isEmpty()) {
                    line.append(" (when absent: ").append(doc.defaultNote()).append(')');
                } else {
                    line.append(" (required)");
                }
                ParamRange.of(doc).ifPresent(r -> line.append(", ").append(r));
                line.append("  ").append(doc.value());
            }
            out.println(line);
        }
    }
}
