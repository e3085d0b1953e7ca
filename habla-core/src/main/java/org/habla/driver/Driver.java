package org.habla.driver;

import java.util.List;
import org.habla.sample.PayloadKind;

/**
 * A native-protocol driver for one robot: it describes the robot's channels and the TCP connections
 * that carry them. Everything about connecting — back-off, telling a lost peer, staleness, the motion
 * watchdog — is the engine's, written once; a driver only declares, per {@link Connection}, whether its peer
 * keeps sending ({@link Liveness}).
 */
public interface Driver {

    /**
     * The reading channel the engine adds to every interface, whatever its driver: the link's state as a
     * {@link LinkReport} record, sent on every change and once a second. Drivers must not declare a channel of this
     * name.
     */
    ChannelDescriptor LINK_CHANNEL = ChannelDescriptor.reading("link", PayloadKind.RECORD, "")
            .withLayout(LinkReport.LAYOUT);

    /** Every channel the robot offers, readings and commands, with their metadata. */
    List<ChannelDescriptor> channels();

    /** The TCP connections to open; readings may come on any of them, commands go where listed. */
    List<Connection> connections();

    /**
     * The connections a client library opens itself (e.g. to an MQTT broker, with TLS), kept by the engine like
     * the {@link #connections()}: back-off, staleness and the motion watchdog are the same. None by default.
     */
    default List<ClientConnection> clientConnections() {
        return List.of();
    }
}
