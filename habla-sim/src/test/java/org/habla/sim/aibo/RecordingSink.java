package org.habla.sim.aibo;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/** A sink that keeps everything the driver's sessions report; safe to read from the test's thread. */
final class RecordingSink implements ReadingSink {

    record Reading(String channel, Payload value) {
    }

    final List<Reading> readings = new CopyOnWriteArrayList<>();
    final List<String> malformed = new CopyOnWriteArrayList<>();
    final List<ObjectNode> info = new CopyOnWriteArrayList<>();

    @Override
    public Channel channel(String name) {
        return Channel.of(value -> reading(name, value), (value, micros) -> reading(name, value, micros));
    }

    @Override
    public void reading(String channel, Payload value) {
        readings.add(new Reading(channel, value));
    }

    @Override
    public void reading(String channel, Payload value, long sourceMicros) {
        readings.add(new Reading(channel, value));
    }

    @Override
    public void malformed(String what) {
        malformed.add(what);
    }

    @Override
    public void robotInfo(ObjectNode node) {
        info.add(node);
    }

    List<Payload> on(String channel) {
        return readings.stream().filter(r -> r.channel().equals(channel)).map(Reading::value).toList();
    }

    /** The newest value on {@code channel}, or null. */
    Payload latest(String channel) {
        List<Payload> all = on(channel);
        return all.isEmpty() ? null : all.get(all.size() - 1);
    }
}
