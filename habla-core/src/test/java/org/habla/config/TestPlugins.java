package org.habla.config;

import java.util.List;
import org.habla.plugin.PluginRegistry;

/** The plugin table of the config, drawing and command tests: the test method types and the {@code robot-sim} driver. */
public final class TestPlugins {

    private TestPlugins() {
    }

    public static PluginRegistry registry() {
        return PluginRegistry.of(TestMethods.providers(), List.of(new TestDriver.Provider()));
    }
}
