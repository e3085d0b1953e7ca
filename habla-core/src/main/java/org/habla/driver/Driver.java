package org.habla.driver;

import java.util.List;

/**
 * A native-protocol driver for one robot: it describes the robot's channels and the TCP connections
 * that carry them. Everything about connecting — back-off, staleness, the motion watchdog — is the
 * engine's, written once.
 */
public interface Driver {

    /** Every channel the robot offers, readings and commands, with their metadata. */
    List<ChannelDescriptor> channels();

    /** The connections to open; readings may come on any of them, commands go where listed. */
    List<Connection> connections();
}
