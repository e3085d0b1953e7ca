package org.habla.daemon;

import java.io.IOException;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigError;
import org.habla.net.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.net.BindAddress;

/**
 * Finds the ports of a config that cannot be listened on, before the daemon listens on any. Each port is
 * tried with a socket that is bound but never listens: the kernel refuses the bind exactly when a listener
 * could not have it, yet nobody can connect to the probe, so a config with one taken port never answers on the
 * others even for a moment. (Another program may still take a port between the probe and the real bind; the
 * daemon then closes what it bound before serving anything.)
 */
final class PortCheck {

    private PortCheck() {
    }

    /** One error per port that cannot be had, at its JSON path; empty when every port is free. */
    static List<ConfigError> unavailable(HablaConfig config) {
        List<ConfigError> errors = new ArrayList<>();
        for (int i = 0; i < config.methods().size(); i++) {
            MethodConfig m = config.methods().get(i);
            if (m.expose().isPresent()) {
                Expose x = m.expose().get();
                String at = "$.methods[" + i + "].expose";
                probe(at, "bind", "port", "control socket '" + x.name() + "'", bindOf(x.bind()), x.port()).ifPresent(errors::add);
            }
        }
        if (config.status().port() > 0) {
            probe("$.status", "bind", "port", "the status endpoint", bindOf(config.status().bind()),
                    config.status().port())
                    .ifPresent(errors::add);
        }
        if (config.status().monitorPort() > 0) {
            probe("$.status", "monitorBind", "monitorPort", "the monitor", bindOf(config.status().monitorBind()),
                    config.status().monitorPort())
                    .ifPresent(errors::add);
        }
        return errors;
    }

    /** The JSON path of the port a control socket's bind error concerns. */
    static ConfigError controlSocketError(HablaConfig config, String methodId, IOException e) {
        for (int i = 0; i < config.methods().size(); i++) {
            if (config.methods().get(i).id().equals(methodId)) {
                return new ConfigError("$.methods[" + i + "].expose.port", e.getMessage());
            }
        }
        return new ConfigError("$", e.getMessage());
    }

    static String bindOf(String bind) {
        return bind == null || bind.isBlank() ? BindAddress.DEFAULT : bind;
    }

    private static java.util.Optional<ConfigError> probe(String at, String bindKey, String portKey, String what,
            String bind, int port) {
        if (port <= 0) {
            return java.util.Optional.empty();
        }
        BindAddress address;
        try {
            address = BindAddress.of(bind);
        } catch (UnknownHostException e) {
            return java.util.Optional.of(new ConfigError(at + "." + bindKey, what + " cannot listen on " + bind
                    + ": not an address of this computer (" + e.getMessage() + ")"));
        }
        try {
            address.probe(port);
            return java.util.Optional.empty();
        } catch (IOException e) {
            return java.util.Optional.of(new ConfigError(at + "." + portKey, what + " cannot listen on " + bind + ":"
                    + port + ": " + e.getMessage() + " (another program has the port, or the address is not this"
                    + " computer's)"));
        }
    }
}
