package org.habla.drivers.iface;

import java.time.Duration;
import java.util.List;
import java.util.stream.Collectors;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;

/** A robot reached through HABLA's interface protocol: the configured channels over one connection. */
final class InterfaceDriver implements Driver {

    private final int port;
    private final List<ChannelDescriptor> channels;
    private final Duration keepAlive;

    InterfaceDriver(int port, InterfaceParams params) {
        this.port = port;
        this.channels = params.descriptors();
        this.keepAlive = Duration.ofMillis(params.keepAliveMs());
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return channels;
    }

    @Override
    public List<Connection> connections() {
        var commands = channels.stream()
                .filter(c -> c.direction() == ChannelDescriptor.Direction.COMMAND)
                .map(ChannelDescriptor::name)
                .collect(Collectors.toSet());
        return List.of(new Connection("interface", port, commands, () -> new InterfaceSession(channels, keepAlive)));
    }
}
