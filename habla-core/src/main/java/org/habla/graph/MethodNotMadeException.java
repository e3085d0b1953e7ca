package org.habla.graph;

import org.habla.config.ConfigError;
import org.habla.config.MethodConfig;

/**
 * A method of the config could not be made when the graph was built: its type lists its ports for the params
 * (so the config is valid), but the constructor refused. The error names the method's JSON path.
 */
public final class MethodNotMadeException extends RuntimeException {

    private final transient ConfigError error;

    MethodNotMadeException(int index, MethodConfig method, Throwable cause) {
        this(new ConfigError("$.methods[" + index + "]", "method '" + method.id() + "' of type '" + method.type()
                + "' cannot be made: " + cause.getMessage()), cause);
    }

    private MethodNotMadeException(ConfigError error, Throwable cause) {
        super(error.toString(), cause);
        this.error = error;
    }

    /** What failed, at the method's path ({@code $.methods[3]}). */
    public ConfigError error() {
        return error;
    }
}
