package org.habla.draw;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Places the boxes of a {@link GraphPicture} for the SVG: one band per {@link Row}, boxes side by side in
 * their band, never overlapping. The order within a band comes from a few barycentre sweeps (each box
 * moves towards the mean position of the boxes it is wired to in the neighbouring bands), which keeps
 * most arrows short and uncrossed; a channel box stays inside its interface's frame. Sizes follow the
 * text in a monospaced font, so the result depends only on the picture.
 *
 * @param nodes  every node's box, by key
 * @param frames every interface frame, by interface id
 * @param bands  every band's rectangle
 * @param width  the picture's width
 * @param height the picture's height
 */
public record Layout(Map<String, Box> nodes, Map<String, Box> frames, Map<Row, Box> bands, double width,
        double height) {

    /** Width of one character of the 12 px monospaced font. */
    static final double CHAR = 7.25;
    /** Height of one line of text. */
    static final double LINE = 15;
    static final double PAD_X = 10;
    static final double PAD_Y = 7;
    static final double GAP_X = 28;
    static final double GAP_Y = 56;
    static final double BAND_PAD = 16;
    static final double CAPTION = 20;
    static final double MARGIN = 16;
    static final double TITLE = 44;
    static final double LEGEND = 40;
    static final int SWEEPS = 4;
    /** Wide enough for the legend. */
    static final double MIN_WIDTH = 720;

    public static Layout of(GraphPicture picture) {
        Map<Row, List<Node>> order = order(picture);
        double left = MARGIN + BAND_PAD + titleColumn();
        Map<Row, Double> rowWidths = new EnumMap<>(Row.class);
        Map<Row, Double> rowHeights = new EnumMap<>(Row.class);
        for (Row row : Row.values()) {
            rowWidths.put(row, rowWidth(row, order.get(row), picture));
            rowHeights.put(row, rowHeight(row, order.get(row)));
        }
        double content = Math.max(240, rowWidths.values().stream().mapToDouble(Double::doubleValue).max().orElse(0));
        double width = Math.max(MIN_WIDTH, left + content + BAND_PAD + MARGIN);
        content = width - left - BAND_PAD - MARGIN;

        Map<String, Box> nodes = new LinkedHashMap<>();
        Map<String, Box> frames = new LinkedHashMap<>();
        Map<Row, Box> bands = new EnumMap<>(Row.class);
        double y = TITLE;
        for (Row row : Row.values()) {
            double bandHeight = rowHeights.get(row) + BAND_PAD * 2;
            bands.put(row, new Box(MARGIN, y, width - 2 * MARGIN, bandHeight));
            double x = left + (content - rowWidths.get(row)) / 2;
            double top = y + BAND_PAD;
            if (row == Row.INTERFACES) {
                for (InterfaceGroup g : groupOrder(order.get(row), picture)) {
                    List<Node> channels = order.get(row).stream().filter(n -> n.group().equals(g.id())).toList();
                    double frameWidth = groupWidth(g, channels);
                    double inner = channels.stream().mapToDouble(Layout::boxWidth).sum() + GAP_X * Math.max(0, channels.size() - 1);
                    double cx = x + (frameWidth - inner) / 2;
                    for (Node n : channels) {
                        nodes.put(n.key(), new Box(cx, top + PAD_Y, boxWidth(n), boxHeight(n)));
                        cx += boxWidth(n) + GAP_X;
                    }
                    frames.put(g.id(), new Box(x, top, frameWidth, rowHeights.get(row)));
                    x += frameWidth + GAP_X;
                }
            } else {
                for (Node n : order.get(row)) {
                    nodes.put(n.key(), new Box(x, top + (rowHeights.get(row) - boxHeight(n)) / 2, boxWidth(n), boxHeight(n)));
                    x += boxWidth(n) + GAP_X;
                }
            }
            y += bandHeight + GAP_Y;
        }
        double height = y - GAP_Y + LEGEND;
        return new Layout(nodes, frames, bands, width, height);
    }

    /** The x where the band titles end and the boxes may start. */
    static double titleColumn() {
        int longest = 0;
        for (Row r : Row.values()) {
            longest = Math.max(longest, r.title().length());
        }
        return longest * CHAR + 12;
    }

    static double boxWidth(Node n) {
        int longest = n.lines().stream().mapToInt(String::length).max().orElse(1);
        return Math.max(64, Math.ceil(longest * CHAR + 2 * PAD_X));
    }

    static double boxHeight(Node n) {
        return n.lines().size() * LINE + 2 * PAD_Y;
    }

    private static double groupWidth(InterfaceGroup g, List<Node> channels) {
        double inner = channels.stream().mapToDouble(Layout::boxWidth).sum() + GAP_X * Math.max(0, channels.size() - 1);
        return Math.max(inner + 2 * PAD_X, Math.ceil(g.title().length() * CHAR + 2 * PAD_X));
    }

    private static double rowWidth(Row row, List<Node> nodes, GraphPicture picture) {
        if (row == Row.INTERFACES) {
            List<InterfaceGroup> groups = picture.groups();
            double w = 0;
            for (InterfaceGroup g : groups) {
                w += groupWidth(g, nodes.stream().filter(n -> n.group().equals(g.id())).toList());
            }
            return w + GAP_X * Math.max(0, groups.size() - 1);
        }
        return nodes.stream().mapToDouble(Layout::boxWidth).sum() + GAP_X * Math.max(0, nodes.size() - 1);
    }

    private static double rowHeight(Row row, List<Node> nodes) {
        double tallest = nodes.stream().mapToDouble(Layout::boxHeight).max().orElse(LINE + 2 * PAD_Y);
        return row == Row.INTERFACES ? tallest + 2 * PAD_Y + CAPTION : tallest;
    }

    /** The interface groups in the order their channels ended up in (groups without channels keep their place). */
    private static List<InterfaceGroup> groupOrder(List<Node> channels, GraphPicture picture) {
        List<InterfaceGroup> groups = new ArrayList<>(picture.groups());
        Map<String, Integer> first = new HashMap<>();
        for (int i = 0; i < channels.size(); i++) {
            first.putIfAbsent(channels.get(i).group(), i);
        }
        List<InterfaceGroup> used = groups.stream().filter(g -> first.containsKey(g.id()))
                .sorted(Comparator.comparingInt(g -> first.get(g.id()))).toList();
        List<InterfaceGroup> out = new ArrayList<>();
        int next = 0;
        for (InterfaceGroup g : groups) {
            out.add(first.containsKey(g.id()) ? used.get(next++) : g);
        }
        return out;
    }

    /** The order of the boxes in each band after the barycentre sweeps. */
    static Map<Row, List<Node>> order(GraphPicture picture) {
        Map<Row, List<Node>> order = new EnumMap<>(Row.class);
        for (Row row : Row.values()) {
            List<Node> nodes = new ArrayList<>(picture.row(row));
            if (row == Row.INTERFACES) {
                List<String> groupIds = picture.groups().stream().map(InterfaceGroup::id).toList();
                nodes.sort(Comparator.comparingInt(n -> groupIds.indexOf(n.group())));
            }
            order.put(row, nodes);
        }
        Row[] rows = Row.values();
        for (int sweep = 0; sweep < SWEEPS; sweep++) {
            for (int r = 1; r < rows.length; r++) {
                reorder(order, rows[r], rows[r - 1], picture);
            }
            for (int r = rows.length - 2; r >= 0; r--) {
                reorder(order, rows[r], rows[r + 1], picture);
            }
        }
        return order;
    }

    private static void reorder(Map<Row, List<Node>> order, Row row, Row neighbour, GraphPicture picture) {
        List<Node> nodes = order.get(row);
        Map<String, Double> at = positions(order.get(neighbour));
        Map<String, Double> own = positions(nodes);
        Map<String, Double> centre = new HashMap<>();
        for (Node n : nodes) {
            double sum = 0;
            int count = 0;
            for (Edge e : picture.edges()) {
                String other = e.from().equals(n.key()) ? e.to() : e.to().equals(n.key()) ? e.from() : null;
                if (other != null && at.containsKey(other)) {
                    sum += at.get(other);
                    count++;
                }
            }
            centre.put(n.key(), count == 0 ? own.get(n.key()) : sum / count);
        }
        Comparator<Node> byCentre = Comparator.comparingDouble(n -> centre.get(n.key()));
        if (row == Row.INTERFACES) {
            Map<String, Double> groupCentre = new HashMap<>();
            Map<String, Integer> groupSize = new HashMap<>();
            for (Node n : nodes) {
                groupCentre.merge(n.group(), centre.get(n.key()), Double::sum);
                groupSize.merge(n.group(), 1, Integer::sum);
            }
            byCentre = Comparator.<Node>comparingDouble(n -> groupCentre.get(n.group()) / groupSize.get(n.group()))
                    .thenComparing(n -> n.group()).thenComparing(byCentre);
        }
        List<Node> sorted = new ArrayList<>(nodes);
        sorted.sort(byCentre.thenComparingDouble(n -> own.get(n.key())));
        order.put(row, sorted);
    }

    /** Each node's place in its band as a fraction of the band's width, so bands of different sizes compare. */
    private static Map<String, Double> positions(List<Node> nodes) {
        Map<String, Double> at = new HashMap<>();
        for (int i = 0; i < nodes.size(); i++) {
            at.put(nodes.get(i).key(), (i + 0.5) / nodes.size());
        }
        return at;
    }
}
