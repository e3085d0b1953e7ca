package org.habla.graph;

import java.util.function.Consumer;
import org.habla.sample.Sample;

/**
 * Where a recording sees an interface: at its edges, never inside it. What comes in from the driver is seen on
 * the reading channels' ports before any subscriber has it; a link change as the interface tells it, before the
 * staleness it causes; a command where the graph hands it to the interface, with what became of it.
 */
final class InterfaceTap {

    private InterfaceTap() {
    }

    /** Has {@code tap} see every reading and every link change of {@code link}. */
    static void attach(InterfaceLink link, GraphTap tap, EngineClock clock) {
        for (String channel : link.readingChannels()) {
            link.reading(channel).tapFirst(s -> tap.reading(link.id(), channel, s));
        }
        link.onLinkChange(up -> tap.link(link.id(), up, clock.nowMicros()));
    }

    /**
     * What a command channel's subscriber does: hands the command to the interface, then shows {@code tap} whether
     * it was written or refused (a command on no connection at all is not an event of the robot's).
     */
    static Consumer<Sample> commands(InterfaceLink link, String channel, GraphTap tap) {
        return sample -> {
            InterfaceCommands.Delivery d = link.command(channel, sample);
            if (d != InterfaceCommands.Delivery.UNROUTED) {
                tap.command(link.id(), channel, sample, d == InterfaceCommands.Delivery.WRITTEN);
            }
        };
    }
}
