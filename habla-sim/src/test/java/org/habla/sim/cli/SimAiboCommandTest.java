package org.habla.sim.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.habla.command.ExitCodes;
import org.habla.cli.Habla;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code habla sim aibo} as a user runs it: its own JVM, Tekkotsu's ports moved by a base, stopped by SIGTERM. */
class SimAiboCommandTest {

    @TempDir
    Path dir;

    @Test
    void badOptionsAreRefusedWithAUsageError() {
        assertThat(Habla.execute("sim", "aibo", "--speed", "0.5")).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(Habla.execute("sim", "aibo", "--teacher", "maybe")).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(Habla.execute("sim", "aibo", "--world", "no-such-world")).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(Habla.execute("sim", "aibo", "--port-base", "80")).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
    }

    @Test
    void theSimulatorServesTekkotsuAndTheGroundTruthUntilTerminated() throws Exception {
        int base = freeBase();
        try (DaemonProcess sim = DaemonProcess.start(dir.resolve("sim.log"), "sim", "aibo", "--port-base",
                Integer.toString(base), "--truth-port", "0", "--speed", "4", "--world", "aibo-arena.json",
                "--teacher", "off")) {
            assertThat(DaemonProcess.awaitPort(base + 20, DaemonProcess.START_MS)).as(sim.output()).isTrue();
            long end = System.nanoTime() + 30_000_000_000L;
            Matcher m = Pattern.compile("ground truth (\\d+)").matcher("");
            while (System.nanoTime() < end && !m.reset(sim.output()).find()) {
                Thread.sleep(50);
            }
            assertThat(m.reset(sim.output()).find()).as(sim.output()).isTrue();
            int truthPort = Integer.parseInt(m.group(1));

            List<String> lines = new ArrayList<>();
            end = System.nanoTime() + 30_000_000_000L;
            while (System.nanoTime() < end && !lines.contains("#World State Serializer")) {
                // one client at a time: the probe above may not have been let go yet
                lines.clear();
                try (Socket c = new Socket(InetAddress.getLoopbackAddress(), base + 20)) {
                    c.setSoTimeout(5_000);
                    OutputStream out = c.getOutputStream();
                    out.write("!hello\n!select \"World State Serializer\"\n!root TekkotsuMon\n"
                            .getBytes(StandardCharsets.US_ASCII));
                    BufferedReader in = new BufferedReader(new InputStreamReader(c.getInputStream(),
                            StandardCharsets.US_ASCII));
                    for (String line = in.readLine(); line != null; line = in.readLine()) {
                        lines.add(line);
                        if (line.equals("#World State Serializer")) {
                            break;
                        }
                    }
                } catch (IOException e) {
                    // refused or reset: try again
                }
                Thread.sleep(lines.isEmpty() ? 100 : 0);
            }
            assertThat(lines).contains("#World State Serializer", "hello");
            byte[] packet = new byte[0];
            end = System.nanoTime() + 30_000_000_000L;
            while (System.nanoTime() < end && packet.length < 374) {
                // the server may still be switching on, or still busy with a client that just left
                try (Socket ws = new Socket(InetAddress.getLoopbackAddress(), base + 31)) {
                    ws.setSoTimeout(5_000);
                    packet = ws.getInputStream().readNBytes(374);
                } catch (IOException e) {
                    Thread.sleep(100);
                }
            }
            assertThat(new String(packet, 0, 6, StandardCharsets.US_ASCII)).isEqualTo("ERS-7\0");
            try (Socket t = new Socket(InetAddress.getLoopbackAddress(), truthPort)) {
                t.setSoTimeout(5_000);
                String line = new BufferedReader(new InputStreamReader(t.getInputStream(), StandardCharsets.UTF_8))
                        .readLine();
                assertThat(line).contains("\"robot\"").contains("\"aibo\"").contains("\"present\":false");
            }
            assertThat(sim.terminate(10_000)).as("ends on SIGTERM").isNotEqualTo(-1);
        }
    }

    /** A port base whose eight Tekkotsu ports are all free now. */
    private static int freeBase() throws IOException {
        SplittableRandom random = new SplittableRandom();
        for (int attempt = 0; attempt < 50; attempt++) {
            // Below the kernel's usual ephemeral range (32768 and up): between this probe and the simulator's
            // bind, a connection another test opens must not take one of these ports as its local port.
            int base = 20_000 + 100 * random.nextInt(127);
            List<ServerSocket> held = new ArrayList<>();
            try {
                for (int n : new int[] {11, 20, 31, 50, 52, 53, 70, 71}) {
                    held.add(new ServerSocket(base + n, 1, InetAddress.getLoopbackAddress()));
                }
                return base;
            } catch (IOException e) {
                // taken; try another base
            } finally {
                for (ServerSocket s : held) {
                    s.close();
                }
            }
        }
        throw new IOException("no free port base found");
    }
}
