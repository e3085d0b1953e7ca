package org.habla.drivers.tekkotsu;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.net.LineFramer;

/**
 * The session on the emergency-stop control (port 10053). The Aibo boots with its emergency stop
 * engaged; the handshake asks for the state and, if so configured, sends {@code start} to release it.
 * {@link #goodbye} engages it again with {@code stop}. The robot's {@code on}/{@code off} lines (also
 * sent when someone double-taps the back) are shown in the status as {@code eStop}; a stop engaged on
 * the robot is never overridden.
 *
 * <p>Lines end in a bare {@code \n}: this server does not strip {@code \r}. A line longer than
 * {@link #MAX_LINE_BYTES} is reported and discarded.
 */
final class EStopSession implements LinkSession {

    private static final int MAX_LINE_BYTES = 256;

    private final boolean release;
    /** Made on the first read, over the connection's stream, which it then reads ahead of. */
    private LineFramer lines;

    EStopSession(boolean release) {
        this.release = release;
    }

    @Override
    public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
        send(out, "refresh");
        if (release) {
            send(out, "start");
        }
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        if (lines == null) {
            lines = new LineFramer(in, MAX_LINE_BYTES);
        }
        String line = TekkotsuLines.next(lines, "the emergency-stop control", sink);
        if (line == null) {
            return;
        }
        String text = line.strip();
        if (text.equals("on") || text.equals("off")) {
            ObjectNode info = JsonNodeFactory.instance.objectNode();
            info.put("eStop", text);
            sink.robotInfo(info);
        } else if (!text.isEmpty()) {
            sink.malformed("the emergency-stop control sent '" + WireInput.abbreviate(text)
                    + "', expected 'on' or 'off'");
        }
    }

    @Override
    public void goodbye(OutputStream out) throws IOException {
        send(out, "stop");
    }

    private static void send(OutputStream out, String command) throws IOException {
        out.write((command + "\n").getBytes(StandardCharsets.US_ASCII));
    }
}
