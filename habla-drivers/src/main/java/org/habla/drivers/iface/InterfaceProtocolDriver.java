package org.habla.drivers.iface;

import java.time.Duration;
import java.util.List;
import java.util.stream.Collectors;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.Liveness;

/** A robot reached through HABLA's interface protocol: the configured channels over one connection. */
final class InterfaceProtocolDriver implements Driver {

    /** The shortest silence that means an interface program is gone. */
    static final Duration MIN_SILENCE = Duration.ofSeconds(3);

    private final int port;
    private final List<ChannelDescriptor> channels;
    private final Duration keepAlive;

    InterfaceProtocolDriver(int port, InterfaceParams params) {
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
        return List.of(new Connection("interface", port, commands, liveness(keepAlive),
                () -> new InterfaceSession(channels, keepAlive)));
    }

    /**
     * The interface program streams its readings and answers every ping (sent each {@code keepAliveMs}) with a
     * pong when it has nothing to report: silence for three pings, and at least {@link #MIN_SILENCE}, means it
     * is gone.
     */
    static Liveness liveness(Duration pingPeriod) {
        Duration threePings = pingPeriod.multipliedBy(3);
        return Liveness.periodic(threePings.compareTo(MIN_SILENCE) > 0 ? threePings : MIN_SILENCE);
    }
}
