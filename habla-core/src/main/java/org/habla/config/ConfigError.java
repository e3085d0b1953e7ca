package org.habla.config;

import java.util.Objects;

/**
 * One thing wrong with a config: where (a JSON path such as {@code $.methods[3].inputs.ranges}) and what.
 */
public record ConfigError(String path, String message) implements Comparable<ConfigError> {

    public ConfigError {
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(message, "message");
    }

    @Override
    public int compareTo(ConfigError o) {
        int c = path.compareTo(o.path);
        return c != 0 ? c : message.compareTo(o.message);
    }

    @Override
    public String toString() {
        return path + ": " + message;
    }
}
