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
}
