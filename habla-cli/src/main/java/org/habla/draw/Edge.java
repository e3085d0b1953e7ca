package org.habla.draw;

import java.util.Objects;

/**
 * One wire of the picture, drawn as an arrow from {@code from} to {@code to}.
 *
 * @param from  the key of the node the data leaves
 * @param to    the key of the node the data reaches
 * @param flow  sensing (up), actuation (down) or lateral
 * @param label what is carried, e.g. {@code ranges → ranges} (output → input)
 */
public record Edge(String from, String to, Flow flow, String label) {

    public Edge {
        Objects.requireNonNull(from, "from");
        Objects.requireNonNull(to, "to");
        Objects.requireNonNull(flow, "flow");
        Objects.requireNonNull(label, "label");
    }
}
