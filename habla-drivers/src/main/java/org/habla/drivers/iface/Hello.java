package org.habla.drivers.iface;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.driver.ChannelDescriptor;
import org.habla.plugin.ParamDefaults;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An interface program's hello: the robot's name and the channels it announces, checked against the channels
 * the config expects. A missing channel, or one of another kind or direction, fails the handshake; extra
 * channels are logged and ignored.
 */
record Hello(String robot, Map<String, ChannelDescriptor> channels) {

    private static final Logger LOG = LoggerFactory.getLogger(Hello.class);

    /** Reads a hello header; throws with what is wrong with it. */
    static Hello parse(ObjectNode h, String protocol) throws IOException {
        if (!"hello".equals(h.path("type").asText())) {
            throw new IOException("the interface program's first line must be a hello, was " + abbreviate(h));
        }
        if (!protocol.equals(h.path("protocol").asText())) {
            throw new IOException("the interface program speaks protocol " + h.get("protocol") + ", not \""
                    + protocol + "\"");
        }
        JsonNode list = h.get("channels");
        if (list == null || !list.isArray()) {
            throw new IOException("the interface program's hello has no \"channels\" array");
        }
        Map<String, ChannelDescriptor> channels = new LinkedHashMap<>();
        for (JsonNode announced : list) {
            // What the program leaves out takes the defaults a config's channel spec takes.
            JsonNode c = announced.isObject() ? ParamDefaults.filled(announced, ChannelSpec.class) : announced;
            ChannelDescriptor d;
            try {
                d = new ChannelSpec(text(c, "name"), text(c, "direction"), text(c, "kind"), text(c, "unit"),
                        c.path("motion").asBoolean(false),
                        c.get("meta") instanceof ObjectNode meta ? meta : JsonNodeFactory.instance.objectNode())
                        .descriptor();
            } catch (IllegalArgumentException e) {
                throw new IOException("the interface program announces a bad channel " + abbreviate(c) + ": "
                        + e.getMessage());
            }
            if (channels.put(d.name(), d) != null) {
                throw new IOException("the interface program announces channel '" + d.name() + "' twice");
            }
        }
        return new Hello(h.path("robot").asText(""), channels);
    }

    /** Throws, naming every problem, unless every expected channel is announced with its kind and direction. */
    void check(List<ChannelDescriptor> expected) throws IOException {
        List<String> problems = new ArrayList<>();
        for (ChannelDescriptor want : expected) {
            ChannelDescriptor got = channels.get(want.name());
            if (got == null) {
                problems.add("channel '" + want.name() + "' is not announced");
            } else if (got.direction() != want.direction() || got.kind() != want.kind()) {
                problems.add("channel '" + want.name() + "' is announced as a " + describe(got)
                        + ", the config expects a " + describe(want));
            } else if (!got.unit().equals(want.unit()) || got.motion() != want.motion()) {
                LOG.warn("interface '{}': channel '{}' is announced as {} {} motion={}, the config says {} {} motion={};"
                        + " using the config", robot, want.name(), got.kind().wireName(), got.unit(), got.motion(),
                        want.kind().wireName(), want.unit(), want.motion());
            }
        }
        if (!problems.isEmpty()) {
            throw new IOException("the interface program" + (robot.isEmpty() ? "" : " of '" + robot + "'")
                    + " does not offer what the config expects: " + String.join("; ", problems));
        }
        List<String> expectedNames = expected.stream().map(ChannelDescriptor::name).toList();
        channels.keySet().stream().filter(n -> !expectedNames.contains(n))
                .forEach(n -> LOG.info("interface '{}': ignoring channel '{}', which the config does not list", robot, n));
    }

    private static String describe(ChannelDescriptor c) {
        return c.kind().wireName() + " " + ChannelSpec.wireName(c.direction());
    }

    private static String text(JsonNode c, String field) {
        JsonNode n = c.get(field);
        return n == null || n.isNull() ? null : n.asText();
    }

    private static String abbreviate(JsonNode n) {
        String s = n.toString();
        return s.length() <= 80 ? s : s.substring(0, 77) + "...";
    }
}
