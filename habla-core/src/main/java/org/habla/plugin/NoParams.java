package org.habla.plugin;

/** The params record of a type that takes no parameters: the config's {@code params} must be empty or absent. */
public record NoParams() {
}
