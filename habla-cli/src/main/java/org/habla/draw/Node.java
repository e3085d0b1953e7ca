package org.habla.draw;

import java.util.List;
import java.util.Objects;

/**
 * One box of the picture.
 *
 * @param key   unique within the picture: {@code method:ID}, {@code socket:NAME} or {@code @IFACE.CHANNEL}
 * @param row   the band it sits in
 * @param lines the text in the box, the first line its name
 * @param group the interface id for a channel box, else empty
 * @param remote whether the method runs on a worker (drawn dashed)
 */
public record Node(String key, Row row, List<String> lines, String group, boolean remote) {

    public Node {
        Objects.requireNonNull(key, "key");
        Objects.requireNonNull(row, "row");
        lines = List.copyOf(lines);
        if (lines.isEmpty()) {
            throw new IllegalArgumentException("a node needs a name");
        }
        Objects.requireNonNull(group, "group");
    }

    /** The first line: the method id, socket name or channel name. */
    public String name() {
        return lines.get(0);
    }
}
