package org.habla.daemon;

import org.habla.bridge.Bridge;
import org.habla.bridge.CommandRole;
import org.habla.config.BridgeConfig;
import org.habla.plugin.BridgeProvider;
import org.habla.plugin.PluginRegistry;

/** Makes the bridges a config lists, each with the command role its params give it. */
final class Bridges {

    private Bridges() {
    }

    static Bridge create(PluginRegistry registry, BridgeConfig config) {
        return make(provider(registry, config), config);
    }

    /** The sockets the bridge may write actions to: those its params list, and no other. */
    static CommandRole role(PluginRegistry registry, BridgeConfig config) {
        return CommandRole.of(actions(provider(registry, config), config));
    }

    private static BridgeProvider<?> provider(PluginRegistry registry, BridgeConfig config) {
        return registry.bridge(config.type()).orElseThrow(() ->
                new IllegalStateException("no bridge type '" + config.type() + "'"));
    }

    @SuppressWarnings("unchecked")
    private static <P extends Record> Bridge make(BridgeProvider<P> provider, BridgeConfig config) {
        return provider.create(config.address(), (P) config.params());
    }

    @SuppressWarnings("unchecked")
    private static <P extends Record> java.util.Set<String> actions(BridgeProvider<P> provider, BridgeConfig config) {
        return provider.actionSockets((P) config.params());
    }
}
