package org.habla.config;

import java.util.Locale;

/**
 * What the daemon does with a method placed on a worker ({@code "host"}) while that worker cannot be
 * reached: {@code none} leaves the method's outputs stale until the worker is back; {@code local} runs the
 * method in the daemon meanwhile, so the graph keeps working at the daemon's computational cost.
 */
public enum Fallback {

    /** The method's outputs stay stale while its worker is lost. */
    NONE,
    /** The method runs in the daemon while its worker is lost. */
    LOCAL;

    /** The name used in configs. */
    public String configName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The fallback named {@code text} in a config. */
    public static Fallback fromConfig(String text) {
        for (Fallback f : values()) {
            if (f.configName().equals(text)) {
                return f;
            }
        }
        throw new IllegalArgumentException("'" + text + "' is not a fallback (write none or local)");
    }
}
