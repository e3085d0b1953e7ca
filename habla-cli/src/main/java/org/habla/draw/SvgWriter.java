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
 * worker are drawn dashed. The output depends only on the picture; the markup is written by {@link SvgDocument}.
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
        SvgDocument svg = new SvgDocument(layout.width(), layout.height())
                .rootAttribute("font-family", FONT).rootAttribute("font-size", "12");
        String title = "HABLA graph of '" + picture.system() + "'";
        svg.element("title").text(title);
        svg.element("defs").open();
        marker(svg, "sensing", DotWriter.SENSING_COLOUR);
        marker(svg, "actuation", DotWriter.ACTUATION_COLOUR);
        marker(svg, "lateral", DotWriter.LATERAL_COLOUR);
        svg.close();
        svg.element("rect").attr("x", 0).attr("y", 0).attr("width", layout.width()).attr("height", layout.height())
                .attr("fill", "white").end();
        svg.element("text").attr("x", Layout.MARGIN).attr("y", 26).attr("font-size", "15")
                .attr("font-weight", "bold").text(title);
        for (Row row : Row.values()) {
            Box b = layout.bands().get(row);
            svg.element("rect").attr("class", "band").attr("x", b.x()).attr("y", b.y()).attr("width", b.w())
                    .attr("height", b.h()).attr("rx", "6").attr("fill", bandColour(row)).attr("stroke", "#bbbbbb")
                    .end();
            svg.element("text").attr("class", "band-title").attr("x", b.x() + Layout.BAND_PAD)
                    .attr("y", b.y() + b.h() / 2 + 4).attr("fill", "#555555").attr("font-weight", "bold")
                    .text(row.title().toUpperCase(Locale.ROOT));
        }
        for (InterfaceGroup g : picture.groups()) {
            Box f = layout.frames().get(g.id());
            svg.element("rect").attr("class", "interface").attr("x", f.x()).attr("y", f.y()).attr("width", f.w())
                    .attr("height", f.h()).attr("rx", "4").attr("fill", "white").attr("stroke", "#888888").end();
            svg.element("text").attr("x", f.centerX()).attr("y", f.bottom() - 7).attr("text-anchor", "middle")
                    .attr("fill", "#333333").text(g.title());
        }
        Map<String, double[]> ends = anchors(picture, layout);
        for (int i = 0; i < picture.edges().size(); i++) {
            edge(svg, picture.edges().get(i), ends.get("from" + i), ends.get("to" + i));
        }
        for (Node node : picture.nodes()) {
            box(svg, node, layout.nodes().get(node.key()));
        }
        legend(svg, layout);
        return svg.render();
    }

    private static void marker(SvgDocument svg, String id, String colour) {
        svg.element("marker").attr("id", id).attr("viewBox", "0 0 10 10").attr("refX", "10").attr("refY", "5")
                .attr("markerWidth", "7").attr("markerHeight", "7").attr("orient", "auto-start-reverse")
                .around(svg.element("path").attr("d", "M0,0 L10,5 L0,10 z").attr("fill", colour));
    }

    private static void box(SvgDocument svg, Node node, Box b) {
        boolean control = node.row() == Row.CONTROL;
        boolean channel = node.row() == Row.INTERFACES;
        svg.element("g").attr("class", "node").attr("id", node.key()).open();
        SvgDocument.Element rect = svg.element("rect").attr("class", "node").attr("x", b.x()).attr("y", b.y())
                .attr("width", b.w()).attr("height", b.h())
                .attr("rx", channel ? SvgDocument.number(b.h() / 2) : control ? "2" : "6")
                .attr("fill", control ? "#fffbe6" : "white").attr("stroke", "#333333");
        if (node.remote()) {
            rect.attr("stroke-dasharray", "5 3");
        }
        rect.end();
        for (int i = 0; i < node.lines().size(); i++) {
            double y = b.y() + Layout.PAD_Y + Layout.LINE * (i + 1) - 4;
            SvgDocument.Element text = svg.element("text").attr("x", b.centerX()).attr("y", y)
                    .attr("text-anchor", "middle");
            if (i == 0) {
                text.attr("font-weight", "bold");
            } else {
                text.attr("fill", "#555555");
            }
            text.text(node.lines().get(i));
        }
        svg.close();
    }

    private static void edge(SvgDocument svg, Edge e, double[] from, double[] to) {
        String kind = e.flow().name().toLowerCase(Locale.ROOT);
        String colour = switch (e.flow()) {
            case SENSING -> DotWriter.SENSING_COLOUR;
            case ACTUATION -> DotWriter.ACTUATION_COLOUR;
            case LATERAL -> DotWriter.LATERAL_COLOUR;
        };
        double bend = e.flow() == Flow.LATERAL ? Math.min(from[1], to[1]) - LATERAL_RISE : (from[1] + to[1]) / 2;
        String d = "M" + n(from[0]) + "," + n(from[1]) + " C" + n(from[0]) + "," + n(bend) + " " + n(to[0]) + ","
                + n(bend) + " " + n(to[0]) + "," + n(to[1]);
        SvgDocument.Element path = svg.element("path").attr("class", "edge " + kind).attr("d", d)
                .attr("fill", "none").attr("stroke", colour).attr("stroke-width", "1.4");
        if (e.flow() == Flow.ACTUATION) {
            path.attr("stroke-dasharray", "6 3");
        }
        path.attr("marker-end", "url(#" + kind + ")").title(e.from() + " → " + e.to() + " (" + e.label() + ")");
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

    private static void legend(SvgDocument svg, Layout layout) {
        double y = layout.height() - 16;
        double x = Layout.MARGIN;
        svg.element("g").attr("class", "legend").attr("font-size", "11").attr("fill", "#333333").open();
        legendItem(svg, x, y, "sensing", DotWriter.SENSING_COLOUR, false, "sensing (up)");
        legendItem(svg, x + 170, y, "actuation", DotWriter.ACTUATION_COLOUR, true, "actuation (down)");
        legendItem(svg, x + 355, y, "lateral", DotWriter.LATERAL_COLOUR, false, "within a layer");
        svg.element("rect").attr("x", x + 530).attr("y", y - 9).attr("width", "24").attr("height", "12")
                .attr("fill", "white").attr("stroke", "#333333").attr("stroke-dasharray", "5 3").end();
        svg.element("text").attr("x", x + 560).attr("y", y + 1).text("method on a worker");
        svg.close();
    }

    private static void legendItem(SvgDocument svg, double x, double y, String kind, String colour, boolean dashed,
            String text) {
        SvgDocument.Element path = svg.element("path")
                .attr("d", "M" + n(x) + "," + n(y - 3) + " L" + n(x + 36) + "," + n(y - 3))
                .attr("stroke", colour).attr("stroke-width", "1.4");
        if (dashed) {
            path.attr("stroke-dasharray", "6 3");
        }
        path.attr("marker-end", "url(#" + kind + ")").end();
        svg.element("text").attr("x", x + 44).attr("y", y + 1).text(text);
    }

    private static String n(double v) {
        return SvgDocument.number(v);
    }
}
