package org.habla.daemon;

import java.io.IOException;
import java.util.List;
import org.habla.config.ConfigError;

/**
 * A port the config names cannot be listened on (another program has it, or the bind address is not this
 * computer's): a config error, each at the JSON path of the port. The daemon does not start, and none of its
 * sockets served anyone.
 */
public final class PortsUnavailableException extends IOException {

    private final List<ConfigError> errors;

    public PortsUnavailableException(List<ConfigError> errors) {
        super(String.join("; ", errors.stream().map(ConfigError::toString).toList()));
        this.errors = List.copyOf(errors);
    }

    /** One error per port, at its JSON path ({@code $.methods[3].expose.port}, {@code $.status.port}). */
    public List<ConfigError> errors() {
        return errors;
    }
}
