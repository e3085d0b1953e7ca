package org.habla.draw;

import java.util.List;

/**
 * The picture as Graphviz dot: one cluster per band (ranked bottom to top), the interface channels
 * framed per interface, sensing arrows solid blue, actuation arrows dashed red. Actuation arrows are
 * written lower-node first with {@code dir=back} so that they keep the bands in order.
 */
public final class DotWriter {

    static final String SENSING_COLOUR = "#1f5fbf";
    static final String ACTUATION_COLOUR = "#c0392b";
    static final String LATERAL_COLOUR = "#555555";

    private DotWriter() {
    }

    public static String write(GraphPicture picture) {
        StringBuilder s = new StringBuilder();
        s.append("digraph habla {\n");
        s.append("  graph [rankdir=BT, newrank=true, fontname=\"Helvetica\", labelloc=t, label=")
                .append(quote("HABLA graph of '" + picture.system() + "'")).append("];\n");
        s.append("  node [shape=box, style=\"rounded,filled\", fillcolor=white, fontname=\"Helvetica\", fontsize=11];\n");
        s.append("  edge [fontname=\"Helvetica\", fontsize=9];\n");
        for (Row row : Row.values()) {
            List<Node> nodes = picture.row(row);
            s.append("  subgraph cluster_").append(row.name().toLowerCase(java.util.Locale.ROOT)).append(" {\n");
            // With rankdir=BT "b" puts a band's title at its top, as in the SVG.
            s.append("    label=").append(quote(row.title())).append("; labelloc=b; style=filled; fillcolor=")
                    .append(quote(SvgWriter.bandColour(row))).append("; color=\"#999999\";\n");
            if (row == Row.INTERFACES) {
                for (int g = 0; g < picture.groups().size(); g++) {
                    InterfaceGroup group = picture.groups().get(g);
                    s.append("    subgraph cluster_interface_").append(g).append(" {\n");
                    s.append("      label=").append(quote(group.title())).append("; style=\"rounded\"; fillcolor=white;\n");
                    for (Node n : nodes) {
                        if (n.group().equals(group.id())) {
                            s.append("      ").append(node(n)).append('\n');
                        }
                    }
                    s.append("    }\n");
                }
            } else {
                for (Node n : nodes) {
                    s.append("    ").append(node(n)).append('\n');
                }
            }
            if (!nodes.isEmpty()) {
                s.append("    { rank=same;");
                nodes.forEach(n -> s.append(' ').append(quote(n.key())).append(';'));
                s.append(" }\n");
            }
            s.append("  }\n");
        }
        for (Edge e : picture.edges()) {
            s.append("  ").append(edge(e)).append('\n');
        }
        s.append("}\n");
        return s.toString();
    }

    /** The statement of one edge, as it appears in the output. */
    static String edge(Edge e) {
        return switch (e.flow()) {
            case SENSING -> quote(e.from()) + " -> " + quote(e.to()) + " [color=\"" + SENSING_COLOUR + "\", tooltip="
                    + quote(e.label()) + "];";
            case ACTUATION -> quote(e.to()) + " -> " + quote(e.from()) + " [dir=back, style=dashed, color=\""
                    + ACTUATION_COLOUR + "\", tooltip=" + quote(e.label()) + "];";
            case LATERAL -> quote(e.from()) + " -> " + quote(e.to()) + " [constraint=false, color=\"" + LATERAL_COLOUR
                    + "\", tooltip=" + quote(e.label()) + "];";
        };
    }

    /** The statement of one node, as it appears in the output. */
    static String node(Node n) {
        String shape = switch (n.row()) {
            case CONTROL -> ", shape=cds";
            case INTERFACES -> ", shape=ellipse";
            default -> n.remote() ? ", style=\"rounded,filled,dashed\"" : "";
        };
        return quote(n.key()) + " [label=" + quote(String.join("\n", n.lines())) + shape + "];";
    }

    static String quote(String text) {
        return '"' + text.replace("\\", "\\\\").replace("\"", "\\\"").replace("\n", "\\n") + '"';
    }
}
