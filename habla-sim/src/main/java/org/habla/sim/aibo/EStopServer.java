package org.habla.sim.aibo;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The emergency-stop control (EStopControllerBehavior, port 10053, running at boot). Lines in:
 * {@code start} releases the stop, {@code stop} engages it, {@code refresh} asks for the state. Lines
 * out: {@code on} (engaged) or {@code off} (released), in reply and whenever the stop changes by any
 * means. Only a bare {@code \n} ends a command: {@code stop\r} is not {@code stop}, as on the robot. A line
 * over {@link #MAX_LINE_BYTES} is skipped and logged.
 */
final class EStopServer implements TekkotsuSocket.Client {

    private static final Logger LOG = LoggerFactory.getLogger(EStopServer.class);
    private static final int MAX_LINE_BYTES = 256;

    private final Ers7Body body;

    EStopServer(Ers7Body body) {
        this.body = body;
    }

    @Override
    public void serve(Socket socket) throws IOException {
        OutputStream out = socket.getOutputStream();
        Consumer<Boolean> tell = stopped -> send(out, stopped);
        body.onEStopChange(tell);
        try {
            LineFramer lines = LineFramer.keepingCarriageReturns(socket.getInputStream(), MAX_LINE_BYTES);
            while (true) {
                String line;
                try {
                    line = lines.readText(StandardCharsets.UTF_8);
                } catch (FrameException e) {
                    if (e.fatal()) {
                        return;
                    }
                    LOG.info("e-stop control: ignored a line: {}", e.getMessage());
                    continue;
                }
                if (line == null) {
                    return;
                }
                switch (line) {
                    case "start" -> body.setEStop(false);
                    case "stop" -> body.setEStop(true);
                    case "refresh" -> send(out, body.eStopped());
                    default -> LOG.info("e-stop control: ignored the line '{}' (expected start, stop or refresh)",
                            Abbreviation.of(line));
                }
            }
        } finally {
            body.removeEStopListener(tell);
        }
    }

    private static void send(OutputStream out, boolean stopped) {
        try {
            synchronized (out) {
                out.write((stopped ? "on\n" : "off\n").getBytes(StandardCharsets.US_ASCII));
                out.flush();
            }
        } catch (IOException e) {
            // the client is leaving; its reader ends the session
        }
    }
}
