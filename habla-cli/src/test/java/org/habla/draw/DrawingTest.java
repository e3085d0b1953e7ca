package org.habla.draw;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import javax.xml.parsers.DocumentBuilderFactory;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.TestPlugins;
import org.habla.testing.TestConfigs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

class DrawingTest {

    private static GraphPicture pioneerLike() throws Exception {
        Path file = TestConfigs.file("valid/pioneer-like.json");
        HablaConfig cfg = new ConfigLoader(TestPlugins.registry()).load(file);
        return GraphPicture.of(cfg, TestPlugins.registry());
    }

    /** A method type as another, but light. */
    private record Light<P extends Record>(org.habla.plugin.MethodProvider<P> of)
            implements org.habla.plugin.MethodProvider<P> {
        @Override
        public String name() {
            return of.name();
        }

        @Override
        public String description() {
            return of.description();
        }

        @Override
        public java.util.Set<org.habla.method.Layer> layers() {
            return of.layers();
        }

        @Override
        public Class<P> paramsType() {
            return of.paramsType();
        }

        @Override
        public org.habla.method.Ports ports(org.habla.method.Layer layer, P params) {
            return of.ports(layer, params);
        }

        @Override
        public org.habla.method.Method create(org.habla.method.Layer layer, P params) {
            return of.create(layer, params);
        }

        @Override
        public boolean light() {
            return true;
        }
    }

    @Test
    void aMethodOnTheThreadThatFeedsItSaysWhoseThreadItIs() throws Exception {
        org.habla.plugin.PluginRegistry base = TestPlugins.registry();
        List<org.habla.plugin.MethodProvider<?>> types = new ArrayList<>();
        base.methods().values().forEach(t -> types.add(t.name().equals("nearest-distance") ? new Light<>(t) : t));
        org.habla.plugin.PluginRegistry registry = org.habla.plugin.PluginRegistry.of(types,
                List.copyOf(base.drivers().values()));
        Path file = TestConfigs.file("valid/pioneer-like.json");
        GraphPicture p = GraphPicture.of(new ConfigLoader(registry).load(file), registry);

        assertThat(p.node("method:nearest").lines()).contains("on sonar's thread");
        assertThat(p.node("method:sonar").lines()).noneMatch(l -> l.startsWith("on "));
        assertThat(pioneerLike().node("method:nearest").lines()).as("not light").noneMatch(l -> l.startsWith("on "));
    }

    @Test
    void pictureHasSocketsMethodsAndUsedChannelsInTheirBands() throws Exception {
        GraphPicture p = pioneerLike();

        assertThat(p.row(Row.CONTROL)).extracting(Node::key).containsExactly("socket:distance_angle", "socket:action");
        assertThat(p.row(Row.VIRTUAL)).extracting(Node::name).containsExactly("distance", "action");
        assertThat(p.row(Row.PROCESSING)).extracting(Node::name).containsExactly("nearest", "safety");
        assertThat(p.row(Row.SENSORS_ACTUATORS)).extracting(Node::name).containsExactly("sonar", "wheels");
        assertThat(p.row(Row.INTERFACES)).extracting(Node::key).containsExactly("@robot.sonar", "@robot.motion");
        assertThat(p.node("method:action").remote()).isTrue();
        assertThat(p.node("socket:distance_angle").lines()).containsExactly("distance_angle", "port 7002");
    }

    @Test
    void sensingRunsUpActuationDownAndSameLayerWiresAreLateral() throws Exception {
        GraphPicture p = pioneerLike();

        assertThat(p.edges()).extracting(e -> e.from() + " " + e.flow() + " " + e.to()).containsExactlyInAnyOrder(
                "@robot.sonar SENSING method:sonar",
                "method:sonar SENSING method:nearest",
                "method:nearest SENSING method:distance",
                "method:distance SENSING socket:distance_angle",
                "socket:action ACTUATION method:action",
                "method:action SENSING socket:action",
                "method:action ACTUATION method:safety",
                "method:nearest LATERAL method:safety",
                "method:safety ACTUATION method:wheels",
                "method:wheels ACTUATION @robot.motion");
    }

    @Test
    void dotHasEveryNodeAndEveryEdge() throws Exception {
        GraphPicture p = pioneerLike();

        String dot = DotWriter.write(p);

        assertThat(dot).startsWith("digraph habla {").endsWith("}\n");
        for (Node n : p.nodes()) {
            assertThat(dot).contains(DotWriter.node(n));
        }
        for (Edge e : p.edges()) {
            assertThat(dot).contains(DotWriter.edge(e));
        }
        assertThat(dot).contains("\"@robot.motion\" -> \"method:wheels\" [dir=back")
                .contains("\"@robot.sonar\" -> \"method:sonar\" [color")
                .contains("label=\"robot: robot-sim at 127.0.0.1:8101\"");
        assertThat(dot.chars().filter(c -> c == '{').count()).isEqualTo(dot.chars().filter(c -> c == '}').count());
    }

    @Test
    void graphvizAcceptsTheDotWhereItIsInstalled(@TempDir Path dir) throws Exception {
        assumeTrue(onPath("dot"), "Graphviz is not installed");
        Path file = dir.resolve("pioneer.dot");
        Files.writeString(file, DotWriter.write(PioneerPicture.build()));

        Process p = new ProcessBuilder("dot", "-Tsvg", file.toString()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);

        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        assertThat(parse(out.substring(out.indexOf("<svg"))).getElementsByTagName("g").getLength())
                .isGreaterThan(PioneerPicture.build().nodes().size());
    }

    @Test
    void mermaidHasEveryNodeAndEveryEdge() throws Exception {
        GraphPicture p = pioneerLike();

        String mermaid = MermaidWriter.write(p);
        Map<String, String> ids = MermaidWriter.ids(p.nodes());

        assertThat(mermaid).startsWith("flowchart BT\n");
        for (Node n : p.nodes()) {
            assertThat(mermaid).containsPattern("\\n\\s+" + ids.get(n.key()) + "[\\[(/]");
        }
        for (Edge e : p.edges()) {
            assertThat(mermaid).contains("  " + MermaidWriter.edge(e, ids) + "\n");
        }
        assertThat(mermaid).contains("c_robot_motion").contains("m_wheels -.-> c_robot_motion")
                .contains("c_robot_sonar --> m_sonar").contains("class m_action remote");
        assertThat(ids.values()).doesNotHaveDuplicates();
    }

    @Test
    void svgIsXmlWithOneBoxPerNodeAndNoBoxesOverlapping() throws Exception {
        GraphPicture p = pioneerLike();

        Document svg = parse(SvgWriter.write(p));

        List<Box> boxes = rects(svg, "node");
        assertThat(boxes).hasSize(p.nodes().size());
        List<Box> frames = rects(svg, "interface");
        assertThat(frames).hasSize(p.groups().size());
        assertNoOverlap(boxes);
        assertNoOverlap(frames);
        NodeList paths = svg.getElementsByTagName("path");
        long arrows = 0;
        for (int i = 0; i < paths.getLength(); i++) {
            if (((Element) paths.item(i)).getAttribute("class").startsWith("edge ")) {
                arrows++;
            }
        }
        assertThat(arrows).isEqualTo(p.edges().size());
    }

    @Test
    void svgPutsEachRowInItsBandFromControlAtTheTopToInterfacesAtTheBottom() throws Exception {
        GraphPicture p = pioneerLike();
        Layout layout = Layout.of(p);

        double previousBottom = -1;
        for (Row row : Row.values()) {
            Box band = layout.bands().get(row);
            assertThat(band.y()).isGreaterThan(previousBottom);
            previousBottom = band.bottom();
            for (Node n : p.row(row)) {
                Box b = layout.nodes().get(n.key());
                assertThat(b.y()).isGreaterThanOrEqualTo(band.y());
                assertThat(b.bottom()).isLessThanOrEqualTo(band.bottom());
                assertThat(b.right()).isLessThanOrEqualTo(layout.width());
            }
        }
        Box frame = layout.frames().get("robot");
        for (Node n : p.row(Row.INTERFACES)) {
            Box b = layout.nodes().get(n.key());
            assertThat(b.x()).isGreaterThanOrEqualTo(frame.x());
            assertThat(b.right()).isLessThanOrEqualTo(frame.right());
        }
    }

    @Test
    void aGraphTheSizeOfFigureThreeKeepsEveryBoxInItsBandAndFrameWithoutOverlaps() {
        GraphPicture p = PioneerPicture.build();
        Layout layout = Layout.of(p);

        Document svg = parse(SvgWriter.write(p));

        assertThat(rects(svg, "node")).hasSize(p.nodes().size());
        assertNoOverlap(rects(svg, "node"));
        assertNoOverlap(rects(svg, "interface"));
        for (Node n : p.nodes()) {
            Box b = layout.nodes().get(n.key());
            Box band = layout.bands().get(n.row());
            assertThat(b.y()).as(n.key()).isGreaterThanOrEqualTo(band.y());
            assertThat(b.bottom()).as(n.key()).isLessThanOrEqualTo(band.bottom());
            assertThat(b.x()).as(n.key()).isGreaterThanOrEqualTo(Layout.MARGIN + Layout.BAND_PAD + Layout.titleColumn());
            assertThat(b.right()).as(n.key()).isLessThanOrEqualTo(band.right());
            if (n.row() == Row.INTERFACES) {
                Box frame = layout.frames().get(n.group());
                assertThat(b.x()).as(n.key()).isGreaterThanOrEqualTo(frame.x());
                assertThat(b.right()).as(n.key()).isLessThanOrEqualTo(frame.right());
            }
        }
    }

    @Test
    void aBoxWiredStraightUpIsDrawnAboveTheBoxItComesFrom() {
        GraphPicture p = PioneerPicture.build();
        Layout layout = Layout.of(p);

        // microphone has one wire down (the audio channel) and one up (audio-processing): nothing pulls it aside.
        double mic = layout.nodes().get("method:microphone").centerX();
        assertThat(layout.nodes().get("@mic.audio").centerX()).isCloseTo(mic, within(1.0));
        assertThat(layout.nodes().get("method:audio").centerX()).isCloseTo(mic, within(1.0));
    }

    @Test
    void everyFormatIsTheSameTextEachTime() throws Exception {
        for (DrawingFormat f : DrawingFormat.values()) {
            assertThat(f.write(pioneerLike())).as(f.name()).isEqualTo(f.write(pioneerLike()));
            assertThat(f.write(PioneerPicture.build())).as(f.name()).isEqualTo(f.write(PioneerPicture.build()));
        }
    }

    @Test
    void textIsEscapedInSvg() {
        GraphPicture p = new GraphPicture("a<b & 'c'", List.of(new Node("method:x", Row.VIRTUAL, List.of("x<y"), "", false)),
                List.of(), List.of());

        String svg = SvgWriter.write(p);

        assertThat(svg).contains("x&lt;y").contains("a&lt;b &amp; &apos;c&apos;");
        assertThat(parse(svg).getDocumentElement().getTagName()).isEqualTo("svg");
    }

    private static boolean onPath(String program) {
        String path = System.getenv("PATH");
        return path != null && java.util.Arrays.stream(path.split(java.io.File.pathSeparator))
                .anyMatch(d -> Files.isExecutable(Path.of(d, program)));
    }

    static Document parse(String xml) {
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            return f.newDocumentBuilder().parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)));
        } catch (Exception e) {
            throw new AssertionError("not well-formed XML: " + e.getMessage(), e);
        }
    }

    static List<Box> rects(Document svg, String cls) {
        List<Box> boxes = new ArrayList<>();
        NodeList rects = svg.getElementsByTagName("rect");
        for (int i = 0; i < rects.getLength(); i++) {
            Element r = (Element) rects.item(i);
            if (r.getAttribute("class").equals(cls)) {
                boxes.add(new Box(Double.parseDouble(r.getAttribute("x")), Double.parseDouble(r.getAttribute("y")),
                        Double.parseDouble(r.getAttribute("width")), Double.parseDouble(r.getAttribute("height"))));
            }
        }
        return boxes;
    }

    static void assertNoOverlap(List<Box> boxes) {
        for (int i = 0; i < boxes.size(); i++) {
            for (int j = i + 1; j < boxes.size(); j++) {
                assertThat(boxes.get(i).overlaps(boxes.get(j))).as("%s overlaps %s", boxes.get(i), boxes.get(j)).isFalse();
            }
        }
    }
}
