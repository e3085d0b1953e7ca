package org.habla.graph;

import java.util.List;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.ReadingSink;

/**
 * What an {@link InterfaceLink} runs on: the channels of its robot and the connections that bring their readings
 * in and take commands out. The graph is built the same way whatever the interface runs on; who builds it chooses:
 * a robot's plugin driver with a kept connection per TCP socket or client library ({@link LiveDriver}), or a
 * recording fed in event by event ({@link RecordedDriver}).
 */
interface InterfaceDriver {

    /**
     * Every channel, readings and commands, with their metadata. The engine adds the {@code link} channel
     * ({@link org.habla.driver.Driver#LINK_CHANNEL}) and tells its record from the connections' states, unless the
     * driver lists it here: then the driver's connections deliver the link records as readings (a recording
     * holds the records the engine told when it was made).
     */
    List<ChannelDescriptor> channels();

    /**
     * The connections of the interface, not started yet; each puts what it decodes into {@code sink} and calls
     * {@code changed} when it goes up or down.
     */
    List<Link> connections(InterfaceConfig config, ReadingSink sink, Runnable changed);
}
