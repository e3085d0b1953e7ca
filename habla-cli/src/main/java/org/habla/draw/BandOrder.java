package org.habla.draw;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The left-to-right order of the boxes in each band: a few barycentre sweeps, down then up, in which each
 * box moves to the mean position of the boxes it is wired to in the neighbouring band. It keeps most
 * arrows short and uncrossed. Channels stay together by interface; ties keep the config's order, so the
 * result depends only on the picture.
 */
final class BandOrder {

    static final int SWEEPS = 4;

    private BandOrder() {
    }

    /** The order of the boxes in each band after the barycentre sweeps. */
    static Map<Row, List<Node>> of(GraphPicture picture) {
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

    /** The interface groups in the order their channels ended up in (groups without channels keep their place). */
    static List<InterfaceGroup> groups(List<Node> channels, GraphPicture picture) {
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
}
