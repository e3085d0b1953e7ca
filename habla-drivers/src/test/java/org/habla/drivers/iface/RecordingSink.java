package org.habla.drivers.iface;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/** A reading sink that keeps everything it is given, for tests. */
final class RecordingSink implements ReadingSink {

    record Reading(String channel, Payload value, long sourceMicros) {
    }

    final List<Reading> readings = new ArrayList<>();
    final List<String> malformed = new ArrayList<>();
    final List<ObjectNode> info = new ArrayList<>();

    @Override
    public Channel channel(String name) {
        return Channel.of(value -> reading(name, value), (value, micros) -> reading(name, value, micros));
    }

    @Override
    public void reading(String channel, Payload value) {
        readings.add(new Reading(channel, value, -1));
    }

    @Override
    public void reading(String channel, Payload value, long sourceMicros) {
        readings.add(new Reading(channel, value, sourceMicros));
    }

    @Override
    public void malformed(String what) {
        malformed.add(what);
    }

    @Override
    public void robotInfo(ObjectNode robotInfo) {
        info.add(robotInfo);
    }
}
