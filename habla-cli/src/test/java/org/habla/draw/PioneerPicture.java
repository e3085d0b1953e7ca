package org.habla.draw;

import java.util.ArrayList;
import java.util.List;

/**
 * A picture the size of the paper's Figure 3 (the Pioneer's graph: six sockets, seventeen methods,
 * three interfaces), built directly so the layout can be tested without the method library.
 */
final class PioneerPicture {

    private PioneerPicture() {
    }

    static GraphPicture build() {
        List<Node> nodes = new ArrayList<>();
        List<Edge> edges = new ArrayList<>();
        String[][] sockets = {{"command", "7001"}, {"distance_angle", "7002"}, {"reward", "7003"}, {"action", "7004"},
                {"pose", "7010"}, {"link", "7011"}};
        for (String[] s : sockets) {
            nodes.add(new Node("socket:" + s[0], Row.CONTROL, List.of(s[0], "port " + s[1]), "", false));
        }
        method(nodes, Row.VIRTUAL, "command", "command");
        method(nodes, Row.VIRTUAL, "distance", "distance-angle");
        method(nodes, Row.VIRTUAL, "reward", "reward");
        method(nodes, Row.VIRTUAL, "action", "action");
        method(nodes, Row.VIRTUAL, "pose", "robot-pose");
        method(nodes, Row.VIRTUAL, "link", "link-state");
        method(nodes, Row.PROCESSING, "nearest", "nearest-distance");
        method(nodes, Row.PROCESSING, "audio", "audio-processing");
        method(nodes, Row.PROCESSING, "notes", "note-recognition");
        method(nodes, Row.PROCESSING, "keys-relay", "pass-through");
        method(nodes, Row.PROCESSING, "safety", "movement-safety");
        method(nodes, Row.PROCESSING, "compose", "motion-composition");
        method(nodes, Row.PROCESSING, "coords", "coordinate-translation");
        method(nodes, Row.SENSORS_ACTUATORS, "sonar", "sonar");
        method(nodes, Row.SENSORS_ACTUATORS, "microphone", "microphone");
        method(nodes, Row.SENSORS_ACTUATORS, "keyboard", "keyboard");
        method(nodes, Row.SENSORS_ACTUATORS, "odometry", "odometry");
        method(nodes, Row.SENSORS_ACTUATORS, "wheels", "wheels");
        channel(nodes, "robot", "sonar");
        channel(nodes, "robot", "odometry");
        channel(nodes, "robot", "motion");
        channel(nodes, "robot", "link");
        channel(nodes, "mic", "audio");
        channel(nodes, "keys", "line");
        up(edges, "@robot.sonar", "method:sonar");
        up(edges, "method:sonar", "method:nearest");
        up(edges, "method:nearest", "method:distance");
        up(edges, "method:distance", "socket:distance_angle");
        up(edges, "@mic.audio", "method:microphone");
        up(edges, "method:microphone", "method:audio");
        edges.add(new Edge("method:audio", "method:notes", Flow.LATERAL, "features → features"));
        up(edges, "method:notes", "method:command");
        up(edges, "method:command", "socket:command");
        up(edges, "@keys.line", "method:keyboard");
        up(edges, "method:keyboard", "method:keys-relay");
        up(edges, "method:keys-relay", "method:reward");
        up(edges, "method:reward", "socket:reward");
        up(edges, "@robot.odometry", "method:odometry");
        up(edges, "method:odometry", "method:coords");
        up(edges, "method:coords", "method:pose");
        up(edges, "method:pose", "socket:pose");
        up(edges, "@robot.link", "method:odometry");
        up(edges, "method:link", "socket:link");
        up(edges, "method:coords", "method:link");
        down(edges, "socket:action", "method:action");
        up(edges, "method:action", "socket:action");
        down(edges, "method:action", "method:safety");
        edges.add(new Edge("method:nearest", "method:safety", Flow.LATERAL, "nearest → nearest"));
        edges.add(new Edge("method:safety", "method:compose", Flow.LATERAL, "motion → motion"));
        down(edges, "method:compose", "method:wheels");
        down(edges, "method:wheels", "@robot.motion");
        List<InterfaceGroup> groups = List.of(new InterfaceGroup("robot", "robot: pioneer at 127.0.0.1:8101"),
                new InterfaceGroup("mic", "mic: pcm-stream at 127.0.0.1:8110"),
                new InterfaceGroup("keys", "keys: text-lines at 127.0.0.1:8111"));
        return new GraphPicture("pioneer", nodes, edges, groups);
    }

    private static void method(List<Node> nodes, Row row, String id, String type) {
        nodes.add(new Node("method:" + id, row, id.equals(type) ? List.of(id) : List.of(id, type), "", false));
    }

    private static void channel(List<Node> nodes, String iface, String channel) {
        nodes.add(new Node("@" + iface + "." + channel, Row.INTERFACES, List.of(channel), iface, false));
    }

    private static void up(List<Edge> edges, String from, String to) {
        edges.add(new Edge(from, to, Flow.SENSING, ""));
    }

    private static void down(List<Edge> edges, String from, String to) {
        edges.add(new Edge(from, to, Flow.ACTUATION, ""));
    }
}
