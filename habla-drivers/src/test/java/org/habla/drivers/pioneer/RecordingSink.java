package org.habla.drivers.pioneer;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/** A reading sink that keeps everything it is given, for tests of the drivers. */
public final class RecordingSink implements ReadingSink {

    /** One reading as it arrived. */
    public record Reading(String channel, Payload value) {
    }

    private final List<Reading> readings = new CopyOnWriteArrayList<>();
    private final List<String> malformed = new CopyOnWriteArrayList<>();
    private final List<ObjectNode> robotInfo = new CopyOnWriteArrayList<>();

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
        reading(channel, value);
    }

    @Override
    public void malformed(String what) {
        malformed.add(what);
    }

    @Override
    public void robotInfo(ObjectNode info) {
        robotInfo.add(info.deepCopy());
    }

    public List<Reading> readings() {
        return List.copyOf(readings);
    }

    /** The values read on one channel, oldest first. */
    public List<Payload> on(String channel) {
        List<Payload> out = new ArrayList<>();
        for (Reading r : readings) {
            if (r.channel().equals(channel)) {
                out.add(r.value());
            }
        }
        return out;
    }

    /** The newest value on a channel. */
    public Payload last(String channel) {
        List<Payload> values = on(channel);
        if (values.isEmpty()) {
            throw new AssertionError("no reading on '" + channel + "' among " + readings);
        }
        return values.get(values.size() - 1);
    }

    public List<String> malformed() {
        return List.copyOf(malformed);
    }

    public List<ObjectNode> robotInfo() {
        return List.copyOf(robotInfo);
    }
}
