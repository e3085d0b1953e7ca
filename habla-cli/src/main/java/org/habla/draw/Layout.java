package org.habla.draw;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Places the boxes of a {@link GraphPicture} for the SVG: one band per {@link Row}, boxes side by side in
 * their band, never overlapping. The order within a band comes from {@link BandOrder}; then each band's
 * boxes slide sideways towards the boxes they are wired to, keeping their order and gaps, so most arrows
 * run straight. A channel box stays inside its interface's frame. Sizes follow the text in a monospaced
 * font, so the result depends only on the picture.
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
    static final int ALIGN_ROUNDS = 4;
    /** Wide enough for the legend. */
    static final double MIN_WIDTH = 720;

    public static Layout of(GraphPicture picture) {
        Map<Row, List<Node>> order = BandOrder.of(picture);
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

        Map<Row, List<Block>> blocks = new EnumMap<>(Row.class);
        Map<Row, double[]> xs = new EnumMap<>(Row.class);
        for (Row row : Row.values()) {
            List<Block> bs = blocks(row, order.get(row), picture);
            blocks.put(row, bs);
            double[] x = new double[bs.size()];
            double at = left + (content - rowWidths.get(row)) / 2;
            for (int i = 0; i < bs.size(); i++) {
                x[i] = at;
                at += bs.get(i).width() + GAP_X;
            }
            xs.put(row, x);
        }
        for (int round = 0; round < ALIGN_ROUNDS; round++) {
            for (Row row : Row.values()) {
                align(row, blocks, xs, picture, left, left + content);
            }
        }

        Map<String, Box> nodes = new LinkedHashMap<>();
        Map<String, Box> frames = new LinkedHashMap<>();
        Map<Row, Box> bands = new EnumMap<>(Row.class);
        double y = TITLE;
        for (Row row : Row.values()) {
            double bandHeight = rowHeights.get(row) + BAND_PAD * 2;
            bands.put(row, new Box(MARGIN, y, width - 2 * MARGIN, bandHeight));
            double top = y + BAND_PAD;
            List<Block> bs = blocks.get(row);
            for (int i = 0; i < bs.size(); i++) {
                Block b = bs.get(i);
                double x = xs.get(row)[i];
                if (b.group() != null) {
                    frames.put(b.group().id(), new Box(x, top, b.width(), rowHeights.get(row)));
                }
                for (int k = 0; k < b.nodes().size(); k++) {
                    Node n = b.nodes().get(k);
                    double boxTop = b.group() != null ? top + PAD_Y : top + (rowHeights.get(row) - boxHeight(n)) / 2;
                    nodes.put(n.key(), new Box(x + b.offsets()[k], boxTop, boxWidth(n), boxHeight(n)));
                }
            }
            y += bandHeight + GAP_Y;
        }
        double height = y - GAP_Y + LEGEND;
        return new Layout(nodes, frames, bands, width, height);
    }

    /**
     * What moves as one in a band: a box, or an interface's frame with its channel boxes.
     *
     * @param nodes   the boxes, left to right
     * @param group   the interface, for a frame; null for a single box
     * @param width   the block's width
     * @param offsets each box's x from the block's left edge
     */
    private record Block(List<Node> nodes, InterfaceGroup group, double width, double[] offsets) {
    }

    private static List<Block> blocks(Row row, List<Node> ordered, GraphPicture picture) {
        List<Block> out = new ArrayList<>();
        if (row != Row.INTERFACES) {
            for (Node n : ordered) {
                out.add(new Block(List.of(n), null, boxWidth(n), new double[] {0}));
            }
            return out;
        }
        for (InterfaceGroup g : BandOrder.groups(ordered, picture)) {
            List<Node> channels = ordered.stream().filter(n -> n.group().equals(g.id())).toList();
            double frameWidth = groupWidth(g, channels);
            double inner = channels.stream().mapToDouble(Layout::boxWidth).sum() + GAP_X * Math.max(0, channels.size() - 1);
            double[] offsets = new double[channels.size()];
            double at = (frameWidth - inner) / 2;
            for (int k = 0; k < channels.size(); k++) {
                offsets[k] = at;
                at += boxWidth(channels.get(k)) + GAP_X;
            }
            out.add(new Block(channels, g, frameWidth, offsets));
        }
        return out;
    }

    /**
     * Moves the blocks of one band towards the boxes they are wired to in the neighbouring bands, keeping
     * their order, the gap between them and the band's bounds; if that cannot be done the band stays as it is.
     */
    private static void align(Row row, Map<Row, List<Block>> blocks, Map<Row, double[]> xs, GraphPicture picture,
            double minX, double maxX) {
        Map<String, Double> centres = new HashMap<>();
        Map<String, Row> rowOf = new HashMap<>();
        for (Map.Entry<Row, List<Block>> e : blocks.entrySet()) {
            double[] x = xs.get(e.getKey());
            for (int i = 0; i < e.getValue().size(); i++) {
                Block b = e.getValue().get(i);
                for (int k = 0; k < b.nodes().size(); k++) {
                    Node n = b.nodes().get(k);
                    centres.put(n.key(), x[i] + b.offsets()[k] + boxWidth(n) / 2);
                    rowOf.put(n.key(), e.getKey());
                }
            }
        }
        List<Block> bs = blocks.get(row);
        double[] current = xs.get(row);
        double[] x = new double[bs.size()];
        for (int i = 0; i < bs.size(); i++) {
            Block b = bs.get(i);
            double sum = 0;
            int count = 0;
            for (int k = 0; k < b.nodes().size(); k++) {
                Node n = b.nodes().get(k);
                double ownOffset = b.offsets()[k] + boxWidth(n) / 2;
                for (Edge e : picture.edges()) {
                    String other = e.from().equals(n.key()) ? e.to() : e.to().equals(n.key()) ? e.from() : null;
                    if (other != null && rowOf.get(other) != row && centres.containsKey(other)) {
                        sum += centres.get(other) - ownOffset;
                        count++;
                    }
                }
            }
            x[i] = count == 0 ? current[i] : sum / count;
        }
        for (int i = 0; i < x.length; i++) {
            x[i] = Math.max(x[i], i == 0 ? minX : x[i - 1] + bs.get(i - 1).width() + GAP_X);
        }
        for (int i = x.length - 1; i >= 0; i--) {
            x[i] = Math.min(x[i], i == x.length - 1 ? maxX - bs.get(i).width() : x[i + 1] - GAP_X - bs.get(i).width());
        }
        for (int i = 0; i < x.length; i++) {
            boolean fits = x[i] >= minX - 1e-6 && (i == 0 || x[i - 1] + bs.get(i - 1).width() + GAP_X <= x[i] + 1e-6);
            if (!fits) {
                return;
            }
        }
        xs.put(row, x);
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

}
