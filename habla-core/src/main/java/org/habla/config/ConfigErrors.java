package org.habla.config;

import java.util.ArrayList;
import java.util.List;

/** The errors found so far while a config is read; every check adds to it and none stops at the first. */
final class ConfigErrors {

    private final List<ConfigError> errors = new ArrayList<>();

    void add(JsonPath path, String message) {
        errors.add(new ConfigError(path.text(), message));
    }

    boolean isEmpty() {
        return errors.isEmpty();
    }

    int size() {
        return errors.size();
    }

    /** Every error, sorted by path then message, without repeats. */
    List<ConfigError> sorted() {
        return errors.stream().distinct().sorted().toList();
    }
}
