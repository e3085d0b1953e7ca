package org.habla.graph;

import java.util.ArrayList;
import java.util.List;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;

/** The channels of a recorded interface, without any connection: what a replay puts in place of a driver. */
final class RecordedDriver implements Driver {

    private final List<ChannelDescriptor> channels = new ArrayList<>();

    RecordedDriver(List<ChannelDescriptor> recorded) {
        for (ChannelDescriptor c : recorded) {
            if (!c.name().equals(LINK_CHANNEL.name())) {
                channels.add(c);
            }
        }
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return List.copyOf(channels);
    }

    @Override
    public List<Connection> connections() {
        return List.of();
    }
}
