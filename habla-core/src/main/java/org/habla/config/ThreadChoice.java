package org.habla.config;

import java.util.Locale;

/**
 * Which thread a method runs on ({@code "thread"} in a method's config): {@code auto} lets the engine run a light
 * method on the thread that delivers to it when the graph allows (docs/architecture.md, "Threads"); {@code own}
 * gives the method a thread of its own whatever its type.
 */
public enum ThreadChoice {

    /** The engine chooses: the delivering thread for a light method fed from one thread, else a thread of its own. */
    AUTO,
    /** A thread of its own. */
    OWN;

    /** The name used in configs. */
    public String configName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The choice named {@code text} in a config. */
    public static ThreadChoice fromConfig(String text) {
        for (ThreadChoice c : values()) {
            if (c.configName().equals(text)) {
                return c;
            }
        }
        throw new IllegalArgumentException("'" + text + "' is not a thread choice (write auto or own)");
    }
}
