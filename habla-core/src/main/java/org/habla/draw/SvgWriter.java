package org.habla.draw;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The picture as a standalone SVG laid out by {@link Layout}, like the paper's figures: the control
 * sockets on top, the virtual, processing and sensors &amp; actuators bands, the interfaces at the bottom;
 * sensing arrows (blue, solid) run up, actuation arrows (red, dashed) run down, wires inside a layer
 * arc above it in grey. Where several arrows meet one side of a box their ends are spread along it. Each
 * arrow carries a {@code <title>} (output → input) that viewers show on hover. Methods placed on a
 * worker are drawn dashed. The output depends only on the picture.
 */
public final class SvgWriter {

    private static final String FONT = "DejaVu Sans Mono, Menlo, Consolas, monospace";
    private static final double LATERAL_RISE = 26;

    private SvgWriter() {
    }

    /** The fill of a band, shared with the dot output. */
    static String bandColour(Row row) {
        return switch (row) {
            case CONTROL -> "#f4f4f4";
            case VIRTUAL -> "#eaf1fb";
            case PROCESSING -> "#eef7ec";
            case SENSORS_ACTUATORS -> "#fdf3e6";
            case INTERFACES -> "#f4f4f4";
        };
    }

    public static String write(GraphPicture picture) {
        Layout layout = Layout.of(picture);
        StringBuilder s = new StringBuilder();
        s.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        s.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(n(layout.width())).append("\" height=\"")
                .append(n(layout.height())).append("\" viewBox=\"0 0 ").append(n(layout.width())).append(' ')
                .append(n(layout.height())).append("\" font-family=\"").append(FONT).append("\" font-size=\"12\">\n");
        String title = "HABLA graph of '" + picture.system() + "'";
        s.append("  <title>").append(esc(title)).append("</title>\n");
        s.append("  <defs>\n");
        marker(s, "sensing", DotWriter.SENSING_COLOUR);
        marker(s, "actuation", DotWriter.ACTUATION_COLOUR);
        marker(s, "lateral", DotWriter.LATERAL_COLOUR);
        s.append("  </defs>\n");
        s.append("  <rect x=\"0\" y=\"0\" width=\"").append(n(layout.width())).append("\" height=\"")
                .append(n(layout.height())).append("\" fill=\"white\"/>\n");
        s.append("  <text x=\"").append(n(Layout.MARGIN)).append("\" y=\"26\" font-size=\"15\" font-weight=\"bold\">")
                .append(esc(title)).append("</text>\n");
        for (Row row : Row.values()) {
            Box b = layout.bands().get(row);
            s.append("  <rect class=\"band\" x=\"").append(n(b.x())).append("\" y=\"").append(n(b.y()))
                    .append("\" width=\"").append(n(b.w())).append("\" height=\"").append(n(b.h()))
                    .append("\" rx=\"6\" fill=\"").append(bandColour(row)).append("\" stroke=\"#bbbbbb\"/>\n");
            s.append("  <text class=\"band-title\" x=\"").append(n(b.x() + Layout.BAND_PAD)).append("\" y=\"")
                    .append(n(b.y() + b.h() / 2 + 4)).append("\" fill=\"#555555\" font-weight=\"bold\">")
                    .append(esc(row.title().toUpperCase(Locale.ROOT))).append("</text>\n");
        }
        for (InterfaceGroup g : picture.groups()) {
            Box f = layout.frames().get(g.id());
            s.append("  <rect class=\"interface\" x=\"").append(n(f.x())).append("\" y=\"").append(n(f.y()))
                    .append("\" width=\"").append(n(f.w())).append("\" height=\"").append(n(f.h()))
                    .append("\" rx=\"4\" fill=\"white\" stroke=\"#888888\"/>\n");
            s.append("  <text x=\"").append(n(f.centerX())).append("\" y=\"").append(n(f.bottom() - 7))
                    .append("\" text-anchor=\"middle\" fill=\"#333333\">").append(esc(g.title())).append("</text>\n");
        }
        Map<String, double[]> ends = anchors(picture, layout);
        for (int i = 0; i < picture.edges().size(); i++) {
            edge(s, picture.edges().get(i), ends.get("from" + i), ends.get("to" + i));
        }
        for (Node node : picture.nodes()) {
            box(s, node, layout.nodes().get(node.key()));
        }
        legend(s, layout);
        s.append("</svg>\n");
        return s.toString();
    }

    private static void marker(StringBuilder s, String id, String colour) {
        s.append("    <marker id=\"").append(id).append("\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" ")
                .append("markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\">")
                .append("<path d=\"M0,0 L10,5 L0,10 z\" fill=\"").append(colour).append("\"/></marker>\n");
    }

    private static void box(StringBuilder s, Node node, Box b) {
        boolean control = node.row() == Row.CONTROL;
        boolean channel = node.row() == Row.INTERFACES;
        s.append("  <g class=\"node\" id=\"").append(esc(node.key())).append("\">\n");
        s.append("    <rect class=\"node\" x=\"").append(n(b.x())).append("\" y=\"").append(n(b.y()))
                .append("\" width=\"").append(n(b.w())).append("\" height=\"").append(n(b.h())).append("\" rx=\"")
                .append(channel ? n(b.h() / 2) : control ? "2" : "6").append("\" fill=\"")
                .append(control ? "#fffbe6" : "white").append("\" stroke=\"#333333\"")
                .append(node.remote() ? " stroke-dasharray=\"5 3\"" : "").append("/>\n");
        for (int i = 0; i < node.lines().size(); i++) {
            double y = b.y() + Layout.PAD_Y + Layout.LINE * (i + 1) - 4;
            s.append("    <text x=\"").append(n(b.centerX())).append("\" y=\"").append(n(y))
                    .append("\" text-anchor=\"middle\"").append(i == 0 ? " font-weight=\"bold\"" : " fill=\"#555555\"")
                    .append('>').append(esc(node.lines().get(i))).append("</text>\n");
        }
        s.append("  </g>\n");
    }

    private static void edge(StringBuilder s, Edge e, double[] from, double[] to) {
        String kind = e.flow().name().toLowerCase(Locale.ROOT);
        String colour = switch (e.flow()) {
            case SENSING -> DotWriter.SENSING_COLOUR;
            case ACTUATION -> DotWriter.ACTUATION_COLOUR;
            case LATERAL -> DotWriter.LATERAL_COLOUR;
        };
        String d;
        if (e.flow() == Flow.LATERAL) {
            double top = Math.min(from[1], to[1]) - LATERAL_RISE;
            d = "M" + n(from[0]) + "," + n(from[1]) + " C" + n(from[0]) + "," + n(top) + " " + n(to[0]) + "," + n(top)
                    + " " + n(to[0]) + "," + n(to[1]);
        } else {
            double mid = (from[1] + to[1]) / 2;
            d = "M" + n(from[0]) + "," + n(from[1]) + " C" + n(from[0]) + "," + n(mid) + " " + n(to[0]) + "," + n(mid)
                    + " " + n(to[0]) + "," + n(to[1]);
        }
        s.append("  <path class=\"edge ").append(kind).append("\" d=\"").append(d).append("\" fill=\"none\" stroke=\"")
                .append(colour).append("\" stroke-width=\"1.4\"")
                .append(e.flow() == Flow.ACTUATION ? " stroke-dasharray=\"6 3\"" : "")
                .append(" marker-end=\"url(#").append(kind).append(")\"><title>")
                .append(esc(e.from() + " → " + e.to() + " (" + e.label() + ")")).append("</title></path>\n");
    }

    /**
     * Where each arrow leaves and meets its boxes: on the side facing the other box (top or bottom; lateral
     * wires use the top), with the ends on one side spread evenly and ordered by where the other box is.
     */
    private static Map<String, double[]> anchors(GraphPicture picture, Layout layout) {
        record End(String name, String node, boolean top, double otherX, int edge) {
        }
        List<End> ends = new ArrayList<>();
        List<Edge> edges = picture.edges();
        for (int i = 0; i < edges.size(); i++) {
            Edge e = edges.get(i);
            Box a = layout.nodes().get(e.from());
            Box b = layout.nodes().get(e.to());
            boolean lateral = e.flow() == Flow.LATERAL;
            boolean aBelow = a.y() > b.y();
            ends.add(new End("from" + i, e.from(), lateral || aBelow, b.centerX(), i));
            ends.add(new End("to" + i, e.to(), lateral || !aBelow, a.centerX(), i));
        }
        Map<String, List<End>> sides = new HashMap<>();
        for (End end : ends) {
            sides.computeIfAbsent(end.node() + (end.top() ? "^" : "v"), k -> new ArrayList<>()).add(end);
        }
        Map<String, double[]> at = new HashMap<>();
        for (List<End> side : sides.values()) {
            side.sort(Comparator.comparingDouble(End::otherX).thenComparingInt(End::edge).thenComparing(End::name));
            Box box = layout.nodes().get(side.get(0).node());
            for (int i = 0; i < side.size(); i++) {
                End end = side.get(i);
                double x = box.x() + box.w() * (i + 1) / (side.size() + 1);
                at.put(end.name(), new double[] {x, end.top() ? box.y() : box.bottom()});
            }
        }
        return at;
    }

    private static void legend(StringBuilder s, Layout layout) {
        double y = layout.height() - 16;
        double x = Layout.MARGIN;
        s.append("  <g class=\"legend\" font-size=\"11\" fill=\"#333333\">\n");
        legendItem(s, x, y, "sensing", DotWriter.SENSING_COLOUR, false, "sensing (up)");
        legendItem(s, x + 170, y, "actuation", DotWriter.ACTUATION_COLOUR, true, "actuation (down)");
        legendItem(s, x + 355, y, "lateral", DotWriter.LATERAL_COLOUR, false, "within a layer");
        s.append("    <rect x=\"").append(n(x + 530)).append("\" y=\"").append(n(y - 9))
                .append("\" width=\"24\" height=\"12\" fill=\"white\" stroke=\"#333333\" stroke-dasharray=\"5 3\"/>\n");
        s.append("    <text x=\"").append(n(x + 560)).append("\" y=\"").append(n(y + 1))
                .append("\">method on a worker</text>\n");
        s.append("  </g>\n");
    }

    private static void legendItem(StringBuilder s, double x, double y, String kind, String colour, boolean dashed,
            String text) {
        s.append("    <path d=\"M").append(n(x)).append(',').append(n(y - 3)).append(" L").append(n(x + 36)).append(',')
                .append(n(y - 3)).append("\" stroke=\"").append(colour).append("\" stroke-width=\"1.4\"")
                .append(dashed ? " stroke-dasharray=\"6 3\"" : "").append(" marker-end=\"url(#").append(kind)
                .append(")\"/>\n");
        s.append("    <text x=\"").append(n(x + 44)).append("\" y=\"").append(n(y + 1)).append("\">").append(esc(text))
                .append("</text>\n");
    }

    /** A coordinate with at most one decimal, the same on every machine. */
    private static String n(double v) {
        double r = Math.round(v * 10) / 10.0;
        return r == Math.rint(r) ? Long.toString((long) r) : String.format(Locale.ROOT, "%.1f", r);
    }

    private static String esc(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")
                .replace("'", "&apos;");
    }
}
