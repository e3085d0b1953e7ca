package org.habla.worker;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.stream.Collectors;
import org.habla.config.ConfigError;
import org.habla.config.ConfigException;
import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.graph.EngineClock;
import org.habla.graph.HostedMethod;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.WorkerProtocol;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;

/**
 * The daemon's place line, carried out: the method it names made from its type, layer and params, with the
 * interface channels it reads and commands bound, ready for a {@link WorkerSession} to run — or the reason it
 * cannot be, as the error code and sentence the daemon is sent.
 */
final class PlaceLine {

    private PlaceLine() {
    }

    /** Why a place line was refused: an error code and a sentence. */
    record Refusal(String code, String message) {
    }

    /**
     * What came of a place line: the method made ({@code refusal} null) or not ({@code hosted} null).
     *
     * @param methodId the method's id as the line gave it, or "?" if it gave none
     */
    record Made(String methodId, HostedMethod hosted, Refusal refusal) {

        static Made refused(String methodId, String code, String message) {
            return new Made(methodId, null, new Refusal(code, message));
        }
    }

    /** Makes the method {@code f} asks for; never throws for what the line says. */
    static Made make(Frame f, PluginRegistry registry, EngineClock clock, ExecutorService backgroundPool) {
        if (!f.type().equals("place")) {
            return Made.refused("?", "not_place", "expected a place line first, got type '" + f.type() + "'");
        }
        String methodId = "?";
        String type;
        Layer layer;
        try {
            methodId = WorkerProtocol.text(f, "method");
            type = WorkerProtocol.text(f, "methodType");
            layer = Layer.fromConfig(WorkerProtocol.text(f, "layer"));
        } catch (FrameException | IllegalArgumentException e) {
            return Made.refused(methodId, "bad_place", String.valueOf(e.getMessage()));
        }
        MethodProvider<?> provider = registry.method(type).orElse(null);
        if (provider == null) {
            return Made.refused(methodId, "unknown_type", "this worker cannot run method type '" + type + "'");
        }
        if (!provider.layers().contains(layer)) {
            return Made.refused(methodId, "bad_place",
                    "type '" + type + "' cannot be placed in the " + layer.configName() + " layer");
        }
        JsonNode params = f.header().get("params");
        Map<String, ChannelDescriptor> channels;
        Map<String, ChannelDescriptor> commandChannels;
        try {
            channels = WorkerProtocol.channels(f, "channels");
            commandChannels = WorkerProtocol.channels(f, "commandChannels");
        } catch (FrameException e) {
            return Made.refused(methodId, "bad_place", e.getMessage());
        }
        try {
            Record bound = ParamsJson.read(params, provider.paramsType());
            HostedMethod h = new HostedMethod(methodId, type, make(provider, layer, bound), clock, backgroundPool);
            channels.forEach(h::bindChannel);
            commandChannels.forEach(h::bindCommandChannel);
            return new Made(methodId, h, null);
        } catch (ConfigException e) {
            return Made.refused(methodId, "bad_params", e.errors().stream().map(ConfigError::toString)
                    .collect(Collectors.joining("; ")));
        } catch (RuntimeException | LinkageError e) {
            return Made.refused(methodId, "cannot_make", "type '" + type + "' cannot be made here: " + e.getMessage());
        }
    }

    private static Method make(MethodProvider<?> provider, Layer layer, Record params) {
        return MethodProvider.make(provider, layer, params);
    }
}
