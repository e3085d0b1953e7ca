package org.habla.driver;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.function.Consumer;
import java.util.function.ObjLongConsumer;
import org.habla.sample.Payload;

/**
 * Where a link session puts what it decodes. Thread-confined to the link's reader. A session takes the handle of
 * each reading channel it writes once ({@link #channel}), when it starts, and writes every reading to the handle:
 * no channel is looked up by name per reading. A session whose wire names the channel of each reading (HABLA's
 * interface protocol, a recording) may write by name.
 */
public interface ReadingSink {

    /** A reading channel of the interface, as a session writes to it. */
    @FunctionalInterface
    interface Channel {

        /** A reading taken at {@code sourceMicros} (microseconds since the epoch). */
        void publish(Payload value, long sourceMicros);

        /** A reading, taken now: by the engine's clock in the engine, by the wall clock where no sink says else. */
        default void publish(Payload value) {
            publish(value, System.currentTimeMillis() * 1_000L);
        }

        /** A channel that hands a reading taken now to {@code now} and one with its time to {@code at}. */
        static Channel of(Consumer<Payload> now, ObjLongConsumer<Payload> at) {
            return new Channel() {
                @Override
                public void publish(Payload value, long sourceMicros) {
                    at.accept(value, sourceMicros);
                }

                @Override
                public void publish(Payload value) {
                    now.accept(value);
                }
            };
        }
    }

    /**
     * The handle of reading channel {@code name}, to keep for the session. A name the interface does not declare
     * (or the engine's own {@code link}) gives a handle that counts and drops what is written to it; a reading of
     * another kind than the channel's is counted as malformed and dropped.
     */
    Channel channel(String name);

    /** A reading on a channel named by the wire, taken now. */
    default void reading(String channel, Payload value) {
        channel(channel).publish(value);
    }

    /** A reading on a channel named by the wire, taken at {@code sourceMicros} (microseconds since the epoch). */
    default void reading(String channel, Payload value, long sourceMicros) {
        channel(channel).publish(value, sourceMicros);
    }

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
