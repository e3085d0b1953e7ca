package org.habla.graph;

import java.util.HashMap;
import java.util.Map;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.method.Shape;

/**
 * The shape each output shows with what feeds it: an output that hands an input on as it comes (a
 * {@code pass-through}, a {@code channel} method) looks like the output or interface channel wired to that input,
 * through any number of such hand-ons, so a socket's hello and the monitor name the fields of what really flows.
 */
final class WiredShapes {

    /** Hand-ons followed at most, so a wiring cycle of relays ends. */
    private static final int MAX_HOPS = 64;

    /** What feeds an input: a method's output, or an interface channel. */
    private record Feed(String methodId, Output<?> output, Shape channel) {
    }

    private final Map<String, Map<String, Feed>> feeds = new HashMap<>();

    /** Says that input {@code input} of method {@code methodId} reads output {@code out} of method {@code fromId}. */
    void fromOutput(String methodId, Input<?> input, String fromId, Output<?> out) {
        feeds.computeIfAbsent(methodId, id -> new HashMap<>()).put(input.name(), new Feed(fromId, out, null));
    }

    /** Says that input {@code input} of method {@code methodId} reads an interface channel. */
    void fromChannel(String methodId, Input<?> input, ChannelDescriptor channel) {
        feeds.computeIfAbsent(methodId, id -> new HashMap<>())
                .put(input.name(), new Feed(null, null, Shape.of(channel)));
    }

    /** The shape output {@code out} of method {@code methodId} shows: its own, or what it hands on. */
    Shape of(String methodId, Output<?> out) {
        String id = methodId;
        Shape shape = out.shape();
        for (int hops = 0; shape.passesOn() != null && hops < MAX_HOPS; hops++) {
            Feed feed = feeds.getOrDefault(id, Map.of()).get(shape.passesOn());
            if (feed == null) {
                return out.shape();
            }
            if (feed.channel() != null) {
                return feed.channel();
            }
            id = feed.methodId();
            shape = feed.output().shape();
        }
        return shape.passesOn() == null ? shape : out.shape();
    }
}
