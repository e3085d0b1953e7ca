package org.habla.drivers.mqtt;

import org.habla.driver.ChannelDescriptor;
import org.habla.plugin.Param;

/**
 * One command channel of an {@code mqtt} interface: every command becomes one message on a topic, its payload
 * made from a template. Commands are never retained, so a device that comes back later does not obey an old one.
 *
 * <pre>{@code {"channel": "lamp_hall", "topic": "zigbee2mqtt/hall_lamp/set", "kind": "record", "device": "hall_lamp"}}</pre>
 */
public record CommandMap(
        @Param("the command channel's name, as in \"@interface.channel\"") String channel,
        @Param("the topic the command is published on (no wildcards)") String topic,
        @Param(value = "the payload kind the channel takes: number, text, record or vector",
                defaultValue = "\"record\"") String kind,
        @Param(value = "the SI unit of its numbers", defaultValue = "\"\"") String unit,
        @Param(value = "the message payload: {{value}} is the command (a number, the text, the record's or "
                + "vector's JSON), {{name}} a field of a record command", defaultValue = "\"{{value}}\"")
        String template,
        @Param(value = "the MQTT quality of service: 0 (at most once) or 1 (at least once)", defaultValue = "1")
        int qos,
        @Param(value = "the device (in \"devices\"): while it is offline its commands are dropped and counted; "
                + "empty: none", defaultValue = "\"\"") String device,
        @Param(value = "true for a command that moves something (dropped while the link is down, stopped by the "
                + "watchdog)", defaultValue = "false") boolean motion) {

    public CommandMap {
        if (channel == null || topic == null) {
            throw new IllegalArgumentException("commands: every command needs a \"channel\" and a \"topic\"");
        }
        TopicFilter.topic(topic);
        if (qos != 0 && qos != 1) {
            throw new IllegalArgumentException("commands: '" + channel + "' has qos " + qos + "; use 0 or 1");
        }
        new PayloadTemplate(template);
        ChannelDescriptor.command(channel, ReadingMap.payloadKind(channel, kind), unit, motion);
    }

    ChannelDescriptor descriptor() {
        return ChannelDescriptor.command(channel, ReadingMap.payloadKind(channel, kind), unit, motion);
    }
}
