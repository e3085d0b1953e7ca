package org.habla.sim.aibo;

import static java.nio.charset.StandardCharsets.US_ASCII;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import org.habla.sim.world.SimClock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The simulated Aibo's line servers read their clients through HABLA's one line reader: a line over a server's
 * limit is skipped and the connection goes on with the next line; the emergency stop counts a {@code \r} as part
 * of the line, the controller drops it.
 */
@Timeout(60)
class TekkotsuLineLimitsTest {

    /** Every read of a reply gives up after this. */
    private static final int READ_TIMEOUT_MS = 10_000;

    private final SimClock clock = new SimClock(4, 0.008);
    private final Ers7Body body = new Ers7Body();
    private TekkotsuServers servers;

    @BeforeEach
    void start() throws Exception {
        servers = new TekkotsuServers(TekkotsuPorts.ANY_FREE, new AiboTime(clock), body, new Microphone(7),
                new SpeakerLog(), at -> null);
    }

    @AfterEach
    void stop() throws Exception {
        servers.close();
    }

    @Test
    void theEmergencyStopSkipsALineOverItsLimitAndAnswersTheNext() throws Exception {
        try (Socket s = new Socket("127.0.0.1", servers.ports().eStop())) {
            s.setSoTimeout(READ_TIMEOUT_MS);
            OutputStream out = s.getOutputStream();
            // 257 bytes with the '\r' (one over the limit of 256), then a line of 10 000 bytes: both skipped.
            out.write(("start" + "x".repeat(251) + "\r\n" + "y".repeat(10_000) + "\nrefresh\n").getBytes(US_ASCII));
            assertThat(new String(s.getInputStream().readNBytes(3), US_ASCII)).as("still engaged, and answering")
                    .isEqualTo("on\n");
            out.write("start\n".getBytes(US_ASCII));
            assertThat(new String(s.getInputStream().readNBytes(4), US_ASCII)).isEqualTo("off\n");
        }
    }

    @Test
    void theControllerSaysALineOverItsLimitWasIgnoredAndTakesTheNext() throws Exception {
        try (Socket s = new Socket("127.0.0.1", servers.ports().controller())) {
            s.setSoTimeout(READ_TIMEOUT_MS);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), US_ASCII));
            s.getOutputStream().write(("!msg " + "z".repeat(5_000) + "\n!hello\r\n").getBytes(US_ASCII));
            assertThat(linesUntil(in, "hello")).contains("line longer than 4096 bytes ignored");
        }
    }

    /** The lines read until one equals {@code last} (bounded by the socket's read time-out). */
    private static String linesUntil(BufferedReader in, String last) throws Exception {
        StringBuilder seen = new StringBuilder();
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            seen.append(line).append('\n');
            if (line.equals(last)) {
                return seen.toString();
            }
        }
        throw new AssertionError("the controller closed before '" + last + "': " + seen);
    }
}
