package org.habla.drivers.tekkotsu;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.net.LineFramer;

/**
 * The session on the Tekkotsu controller (menu server, port 10020), which switches the other
 * servers on: the Aibo boots with only the controller, the consoles and the emergency-stop control
 * listening.
 *
 * <p>Activating a menu item toggles it, and its displayed name carries its state: {@code X} (never
 * started), {@code -X} (stopped), {@code #X} (running). {@code !select "X"} and {@code !select "-X"}
 * can therefore only ever start X, so the handshake sends both for every item: harmless when X is
 * already running, when X does not exist in this Tekkotsu version, and on every reconnection.
 * Replies (menu refreshes, status text) are read and ignored, except {@code hello} (the count of
 * greetings since boot, which tells a reboot) and {@code load} (a server announcing its port),
 * which go to the status. A reply line longer than {@link #MAX_LINE_BYTES} is reported and counts as an
 * empty line, so the lines of a message are still counted right.
 */
final class ControllerSession implements LinkSession {

    private static final int MAX_LINE_BYTES = 4_096;

    private final List<String> commands;
    /** Made on the first read, over the connection's stream, which it then reads ahead of. */
    private LineFramer lines;
    private final List<String> message = new ArrayList<>();
    private int linesExpected;

    ControllerSession(List<String> commands) {
        this.commands = List.copyOf(commands);
    }

    /**
     * The commands that switch {@code servers} on; first, if {@code cameraSkip} is present, the raw
     * camera is set to TCP and that resolution (so its socket is made that way when it starts).
     */
    static List<String> startCommands(List<String> servers, Optional<Integer> cameraSkip) {
        List<String> out = new ArrayList<>();
        out.add("!hello");
        cameraSkip.ifPresent(skip -> {
            out.add("!set vision.rawcam.transport=TCP");
            out.add("!set vision.rawcam.y_skip=" + skip);
            out.add("!set vision.rawcam.uv_skip=" + (skip + 1));
        });
        for (String name : servers) {
            out.add("!select \"" + name + "\"");
            out.add("!select \"-" + name + "\"");
        }
        return List.copyOf(out);
    }

    List<String> commands() {
        return commands;
    }

    @Override
    public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
        StringBuilder text = new StringBuilder();
        for (String c : commands) {
            text.append(c).append('\n');
        }
        out.write(text.toString().getBytes(StandardCharsets.UTF_8));
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        if (lines == null) {
            lines = new LineFramer(in, MAX_LINE_BYTES);
        }
        String line = TekkotsuLines.next(lines, "the Tekkotsu controller", sink);
        if (line == null) {
            line = ""; // a discarded line still counts in its message
        }
        if (linesExpected > 0) {
            message.add(line);
            if (--linesExpected == 0) {
                report(sink);
            }
            return;
        }
        if (line.equals("hello")) {
            start(line, 1);
        } else if (line.equals("load")) {
            start(line, 4);
        }
    }

    private void start(String kind, int following) {
        message.clear();
        message.add(kind);
        linesExpected = following;
    }

    private void report(ReadingSink sink) {
        ObjectNode info = JsonNodeFactory.instance.objectNode();
        if (message.get(0).equals("hello")) {
            try {
                info.put("controllerHellos", Long.parseLong(message.get(1).strip()));
            } catch (NumberFormatException e) {
                sink.malformed("the Tekkotsu controller answered hello with '"
                        + WireInput.abbreviate(message.get(1)) + "', not a count");
                return;
            }
        } else {
            info.put("lastServerStarted", message.get(2) + " on port " + message.get(3));
        }
        sink.robotInfo(info);
    }
}
