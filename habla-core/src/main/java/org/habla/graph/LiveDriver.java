package org.habla.graph;

import java.util.ArrayList;
import java.util.List;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.ClientConnection;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.ReadingSink;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.PluginRegistry;

/**
 * A robot's plugin {@link Driver} as an interface runs on it: its channels, and a link the engine keeps for each
 * of its connections — a {@link ConnectionLink} per TCP connection, a {@link ClientLink} per client library's.
 */
final class LiveDriver implements InterfaceDriver {

    private final Driver driver;

    LiveDriver(Driver driver) {
        this.driver = driver;
    }

    /** The driver of a configured interface, made by its provider; connects to nothing yet. */
    @SuppressWarnings({"unchecked", "rawtypes"})
    static LiveDriver create(PluginRegistry registry, InterfaceConfig ic) {
        DriverProvider provider = registry.driver(ic.driver()).orElseThrow(() ->
                new IllegalStateException("no driver type '" + ic.driver() + "'"));
        return new LiveDriver(provider.create(ic.address(), ic.params()));
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return driver.channels();
    }

    /** The names of the driver's connections (TCP and client library's), in its order; none is opened. */
    List<String> connectionNames() {
        List<String> names = new ArrayList<>();
        driver.connections().forEach(c -> names.add(c.name()));
        driver.clientConnections().forEach(c -> names.add(c.name()));
        return names;
    }

    @Override
    public List<Link> connections(InterfaceConfig config, ReadingSink sink, Runnable changed) {
        List<Link> links = new ArrayList<>();
        for (Connection c : driver.connections()) {
            links.add(new ConnectionLink(config.id(), config.address().host(), c, config.reconnect(), sink, changed));
        }
        for (ClientConnection c : driver.clientConnections()) {
            links.add(new ClientLink(config.id(), c, config.reconnect(), sink, changed));
        }
        return links;
    }
}
