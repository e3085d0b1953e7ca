package org.habla.draw;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The picture as a Mermaid flowchart (for Markdown pages): one subgraph per band, drawn bottom to top,
 * sensing arrows solid ({@code -->}), actuation arrows dotted ({@code -.->}), lateral wires plain. Node
 * ids are the keys made safe for Mermaid ({@code m_sonar}, {@code s_distance_angle}, {@code c_robot_sonar}).
 * Mermaid lays the chart out by itself, so its picture is a sketch; the SVG output keeps the bands exactly.
 */
public final class MermaidWriter {

    private MermaidWriter() {
    }

    public static String write(GraphPicture picture) {
        Map<String, String> ids = ids(picture.nodes());
        StringBuilder s = new StringBuilder("flowchart BT\n");
        for (Row row : Row.values()) {
            List<Node> nodes = picture.row(row);
            s.append("  subgraph ").append(row.name().toLowerCase(java.util.Locale.ROOT)).append("[\"")
                    .append(text(row.title())).append("\"]\n");
            if (row == Row.INTERFACES) {
                for (int g = 0; g < picture.groups().size(); g++) {
                    InterfaceGroup group = picture.groups().get(g);
                    s.append("    subgraph interface_").append(g).append("[\"").append(text(group.title())).append("\"]\n");
                    for (Node n : nodes) {
                        if (n.group().equals(group.id())) {
                            s.append("      ").append(node(n, ids)).append('\n');
                        }
                    }
                    s.append("    end\n");
                }
            } else {
                for (Node n : nodes) {
                    s.append("    ").append(node(n, ids)).append('\n');
                }
            }
            s.append("  end\n");
        }
        for (Edge e : picture.edges()) {
            s.append("  ").append(edge(e, ids)).append('\n');
        }
        s.append("  classDef remote stroke-dasharray: 4 3\n");
        picture.nodes().stream().filter(Node::remote).forEach(n -> s.append("  class ").append(ids.get(n.key()))
                .append(" remote\n"));
        return s.toString();
    }

    /** The Mermaid id of every node, by key. */
    static Map<String, String> ids(List<Node> nodes) {
        Map<String, String> ids = new HashMap<>();
        Set<String> taken = new HashSet<>();
        for (Node n : nodes) {
            String prefix = switch (n.row()) {
                case CONTROL -> "s_";
                case INTERFACES -> "c_";
                default -> "m_";
            };
            String bare = n.key().substring(n.key().startsWith("@") ? 1 : n.key().indexOf(':') + 1);
            String id = prefix + bare.replaceAll("[^A-Za-z0-9_]", "_");
            String unique = id;
            for (int i = 2; !taken.add(unique); i++) {
                unique = id + "_" + i;
            }
            ids.put(n.key(), unique);
        }
        return ids;
    }

    static String edge(Edge e, Map<String, String> ids) {
        String arrow = switch (e.flow()) {
            case SENSING -> " --> ";
            case ACTUATION -> " -.-> ";
            case LATERAL -> " --- ";
        };
        return ids.get(e.from()) + arrow + ids.get(e.to());
    }

    private static String node(Node n, Map<String, String> ids) {
        String label = text(String.join("\n", n.lines())).replace("\n", "<br/>");
        String id = ids.get(n.key());
        return switch (n.row()) {
            case CONTROL -> id + "[/\"" + label + "\"/]";
            case INTERFACES -> id + "([\"" + label + "\"])";
            default -> id + "[\"" + label + "\"]";
        };
    }

    private static String text(String s) {
        return s.replace("&", "#amp;").replace("\"", "#quot;").replace("<", "#lt;").replace(">", "#gt;");
    }
}
