package org.habla.drivers.mqtt;

import java.util.Map;
import org.habla.driver.ChannelDescriptor;
import org.habla.plugin.Param;
import org.habla.sample.PayloadKind;

/**
 * One reading channel of an {@code mqtt} interface: the messages on a topic filter, or one JSON field of them.
 *
 * <pre>{@code {"channel": "motion_hall", "topic": "zigbee2mqtt/hall_motion", "field": "occupancy",
 *  "device": "hall_motion"}}</pre>
 */
public record ReadingMap(
        @Param("the reading channel's name, as in \"@interface.channel\"") String channel,
        @Param("the topic filter whose messages feed it; '+' and a final '#' are wildcards") String topic,
        @Param(value = "the JSON field to read, dots for nested objects (\"AM2301.Temperature\"); "
                + "empty: the whole payload", defaultValue = "\"\"") String field,
        @Param(value = "the payload kind: number, text, record or vector", defaultValue = "\"number\"") String kind,
        @Param(value = "the SI unit of its numbers", defaultValue = "\"\"") String unit,
        @Param(value = "the device (in \"devices\") whose availability makes this channel stale while it is "
                + "offline; empty: none", defaultValue = "\"\"") String device,
        @Param(value = "text values and what number each reads as, for kind number (e.g. {\"ON\": 1, \"OFF\": 0}); "
                + "true/false, on/off, open/closed and online/offline are known without it",
                defaultValue = "{}") Map<String, Double> values) {

    public ReadingMap {
        values = Map.copyOf(values);
        if (channel == null || topic == null) {
            throw new IllegalArgumentException("readings: every reading needs a \"channel\" and a \"topic\"");
        }
        new TopicFilter(topic);
        PayloadKind k = payloadKind(channel, kind);
        if (!values.isEmpty() && k != PayloadKind.NUMBER) {
            throw new IllegalArgumentException("readings: '" + channel + "' maps text values but is not a number");
        }
        ChannelDescriptor.reading(channel, k, unit);
    }

    TopicFilter filter() {
        return new TopicFilter(topic);
    }

    PayloadKind payloadKind() {
        return payloadKind(channel, kind);
    }

    ChannelDescriptor descriptor() {
        return ChannelDescriptor.reading(channel, payloadKind(), unit);
    }

    static PayloadKind payloadKind(String channel, String kind) {
        return switch (kind) {
            case "number" -> PayloadKind.NUMBER;
            case "text" -> PayloadKind.TEXT;
            case "record" -> PayloadKind.RECORD;
            case "vector" -> PayloadKind.VECTOR;
            default -> throw new IllegalArgumentException("'" + channel + "' has kind '" + kind
                    + "'; an MQTT channel is a number, text, record or vector");
        };
    }
}
