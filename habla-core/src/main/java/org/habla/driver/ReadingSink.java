package org.habla.driver;

import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.sample.Payload;

/** Where a link session puts what it decodes. Thread-confined to the link's reader. */
public interface ReadingSink {

    /** A reading on a channel, taken now. */
    void reading(String channel, Payload value);

    /** A reading on a channel taken at {@code sourceMicros} (microseconds since the epoch). */
    void reading(String channel, Payload value, long sourceMicros);

    /** Input that could not be decoded and was dropped (a bad checksum, a truncated packet): counted and logged. */
    void malformed(String what);

    /** Facts learnt from the robot (its name, model, firmware), shown in the status. */
    void robotInfo(ObjectNode info);

    /**
     * The device behind a reading channel went away or came back while the link itself stayed up (e.g. a
     * sensor's availability topic said {@code offline}). While a channel is unavailable, every method that
     * depends on it is stale, as if its link were down. Channels are available until said otherwise. A sink
     * that does not track devices ignores this.
     *
     * @param why what the device said, for the status and the clients
     */
    default void availability(String channel, boolean available, String why) {
    }

    /**
     * The state of a device behind the link — a sensor, a lamp, the radio bridge they hang on — as the driver
     * learns it, for the status and the log: {@code habla status} lists each device with its state, so an offline
     * one is named. Telling a device's state changes nothing else: which channels go stale is
     * {@link #availability}'s to say, which commands are refused the session's. A fresh session tells its devices
     * again; until it does, none is listed. A sink that does not track devices ignores this.
     *
     * @param device the device's name, as the driver's params give it
     * @param detail what said so (e.g. {@code "zigbee2mqtt/hall_motion/availability says offline"})
     */
    default void device(String device, boolean online, String detail) {
    }
}
