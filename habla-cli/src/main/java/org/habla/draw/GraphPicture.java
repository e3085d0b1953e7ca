package org.habla.draw;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.habla.config.ChannelRef;
import org.habla.net.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Source;
import org.habla.graph.ThreadPlan;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;

/**
 * What the picture of a config shows, before any layout: the boxes (control sockets, methods by layer,
 * the interface channels the graph uses) and the arrows between them, each sensing, actuation or
 * lateral. Built from a valid config; the order of everything follows the config, so the same config
 * always gives the same picture. A method that runs on the thread that delivers to it ({@link ThreadPlan}) says
 * whose thread that is in its box: {@code on @robot/main's reader}, {@code on sonar's thread}.
 */
public record GraphPicture(String system, List<Node> nodes, List<Edge> edges, List<InterfaceGroup> groups) {

    public GraphPicture {
        nodes = List.copyOf(nodes);
        edges = List.copyOf(edges);
        groups = List.copyOf(groups);
    }

    /** The threads of {@code cfg}'s methods; none if a driver cannot be made to count its connections. */
    private static Optional<ThreadPlan> threadPlan(HablaConfig cfg, PluginRegistry registry) {
        try {
            return Optional.of(ThreadPlan.of(cfg, registry));
        } catch (RuntimeException e) {
            return Optional.empty();
        }
    }

    /** The picture of {@code cfg}; {@code registry} makes each method once to learn its outputs. */
    public static GraphPicture of(HablaConfig cfg, PluginRegistry registry) {
        Map<String, Node> nodes = new LinkedHashMap<>();
        List<Edge> edges = new ArrayList<>();
        for (MethodConfig m : cfg.methods()) {
            Optional<Expose> expose = m.expose();
            if (expose.isPresent()) {
                Expose e = expose.get();
                String port = (e.bind().equals("127.0.0.1") ? "" : e.bind() + ":") + e.port();
                nodes.put(socketKey(e), new Node(socketKey(e), Row.CONTROL, List.of(e.name(), "port " + port), "", false));
            }
        }
        Optional<ThreadPlan> threads = threadPlan(cfg, registry);
        for (MethodConfig m : cfg.methods()) {
            List<String> lines = new ArrayList<>();
            lines.add(m.id());
            if (!m.type().equals(m.id())) {
                lines.add(m.type());
            }
            m.host().ifPresent(h -> lines.add("on " + h));
            threads.map(t -> t.choice(m.id())).filter(ThreadPlan.Choice::inline)
                    .ifPresent(c -> lines.add("on " + c.where()));
            nodes.put(methodKey(m.id()), new Node(methodKey(m.id()), Row.of(m.layer()), lines, "", m.host().isPresent()));
        }
        List<InterfaceGroup> groups = new ArrayList<>();
        for (InterfaceConfig i : cfg.interfaces()) {
            groups.add(new InterfaceGroup(i.id(), i.id() + ": " + i.driver() + " at " + i.address()));
            for (String channel : usedChannels(cfg, i.id())) {
                String key = "@" + i.id() + "." + channel;
                nodes.put(key, new Node(key, Row.INTERFACES, List.of(channel), i.id(), false));
            }
        }
        for (MethodConfig m : cfg.methods()) {
            String to = methodKey(m.id());
            for (Map.Entry<String, Source> in : m.inputs().entrySet().stream().sorted(Map.Entry.comparingByKey()).toList()) {
                switch (in.getValue()) {
                    case Source.Channel c -> edges.add(new Edge(c.text(), to, Flow.SENSING, c.channel() + " → " + in.getKey()));
                    case Source.Control c -> edges.add(new Edge(socketKey(m.expose().orElseThrow()), to, Flow.ACTUATION,
                            "control → " + in.getKey()));
                    case Source.MethodOutput o -> {
                        Layer from = cfg.method(o.methodId()).orElseThrow().layer();
                        edges.add(new Edge(methodKey(o.methodId()), to, flow(from, m.layer()),
                                o.output() + " → " + in.getKey()));
                    }
                }
            }
            for (Map.Entry<String, ChannelRef> c : m.commands().entrySet().stream().sorted(Map.Entry.comparingByKey()).toList()) {
                edges.add(new Edge(to, c.getValue().text(), Flow.ACTUATION, c.getKey() + " → " + c.getValue().channel()));
            }
            if (m.expose().isPresent()) {
                for (String out : outputs(m, registry)) {
                    edges.add(new Edge(to, socketKey(m.expose().get()), Flow.SENSING, out));
                }
            }
        }
        return new GraphPicture(cfg.system(), new ArrayList<>(nodes.values()), edges, groups);
    }

    /** The nodes of one band, in picture order. */
    public List<Node> row(Row row) {
        return nodes.stream().filter(n -> n.row() == row).toList();
    }

    /** The node with this key. */
    public Node node(String key) {
        return nodes.stream().filter(n -> n.key().equals(key)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no node " + key));
    }

    static String methodKey(String id) {
        return "method:" + id;
    }

    static String socketKey(Expose e) {
        return "socket:" + e.name();
    }

    private static Flow flow(Layer from, Layer to) {
        int c = Integer.compare(from.ordinal(), to.ordinal());
        return c < 0 ? Flow.SENSING : c > 0 ? Flow.ACTUATION : Flow.LATERAL;
    }

    /** The channels of an interface the graph reads or writes, in the order the config first names them. */
    private static List<String> usedChannels(HablaConfig cfg, String iface) {
        List<String> used = new ArrayList<>();
        for (MethodConfig m : cfg.methods()) {
            m.inputs().entrySet().stream().sorted(Map.Entry.comparingByKey()).map(Map.Entry::getValue)
                    .filter(s -> s instanceof Source.Channel c && c.interfaceId().equals(iface))
                    .map(s -> ((Source.Channel) s).channel()).filter(c -> !used.contains(c)).forEach(used::add);
            m.commands().entrySet().stream().sorted(Map.Entry.comparingByKey()).map(Map.Entry::getValue)
                    .filter(c -> c.interfaceId().equals(iface))
                    .map(ChannelRef::channel).filter(c -> !used.contains(c)).forEach(used::add);
        }
        return used;
    }

    /** The output names of an exposed method, as its type lists them (the config check read them already). */
    private static List<String> outputs(MethodConfig m, PluginRegistry registry) {
        return registry.method(m.type()).map(p -> ports(p, m).outputs().stream().map(OutputPort::name).toList())
                .orElse(List.of());
    }

    private static <P extends Record> Ports ports(MethodProvider<P> provider, MethodConfig m) {
        return provider.ports(m.layer(), provider.paramsType().cast(m.params()));
    }
}
