package org.habla.config;

/** A channel of an interface, written {@code "@interfaceId.channel"} in configs. */
public record ChannelRef(String interfaceId, String channel) {

    public String text() {
        return "@" + interfaceId + "." + channel;
    }
}
