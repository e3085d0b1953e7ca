package org.habla.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The example in {@code examples/interface-python}: its config is valid as shipped, and the Python rover
 * behind the daemon (each in its own process, as a user runs them) is read and driven over the control
 * sockets: the front range shrinks while it drives towards the wall and stays put once the client is
 * silent and the watchdog has stopped it.
 */
@Timeout(90)
class PythonInterfaceExampleTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path EXAMPLE = Paths.get("..", "examples", "interface-python").toAbsolutePath().normalize();

    @Test
    void theShippedConfigIsValidAndWiresRangesUpAndMotionDown() throws Exception {
        HablaConfig cfg = new ConfigLoader(PluginRegistry.discover()).load(EXAMPLE.resolve("habla.json"));

        assertThat(cfg.iface("rover").orElseThrow().driver()).isEqualTo("habla");
        assertThat(cfg.method("ranges").orElseThrow().expose().orElseThrow().port()).isEqualTo(7020);
        assertThat(cfg.method("drive").orElseThrow().expose().orElseThrow().name()).isEqualTo("motion");
        assertThat(cfg.method("wheels").orElseThrow().commands().get("out").text()).isEqualTo("@rover.motion");
    }

    @Test
    void theConfigReferenceShowsTheShippedConfigAsItsCompleteExample() throws Exception {
        String doc = Files.readString(EXAMPLE.resolve("../../docs/config.md").normalize());
        int start = doc.indexOf("```json\n{\n  \"$schema\"");
        assertThat(start).as("docs/config.md has the complete example").isNotNegative();
        int from = doc.indexOf('\n', start) + 1;
        String documented = doc.substring(from, doc.indexOf("```", from));

        assertThat(JSON.readTree(documented)).isEqualTo(JSON.readTree(EXAMPLE.resolve("habla.json").toFile()));
    }

    @Test
    void theRoverIsReadAndDrivenThroughTheDaemon(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        Path cfg = tmp.resolve("habla.json");
        Files.writeString(cfg, onPorts(ports[0], ports[1], ports[2], ports[3]).toPrettyString());
        Process rover = new ProcessBuilder("python3", EXAMPLE.resolve("rover.py").toString(), "--port",
                String.valueOf(ports[0]), "--start", "1.0", "2.0", "0.0")
                .redirectErrorStream(true).redirectOutput(tmp.resolve("rover.log").toFile()).start();
        try (DaemonProcess daemon = DaemonProcess.start(tmp.resolve("daemon.log"), "run", cfg.toString())) {
            assertThat(awaitLine(tmp.resolve("rover.log"), "rover listening on", 10_000))
                    .as(log(tmp, "rover.log")).isTrue();
            assertThat(DaemonProcess.awaitPort(ports[1], DaemonProcess.START_MS)).as(daemon.output()).isTrue();
            assertThat(DaemonProcess.awaitPort(ports[2], DaemonProcess.START_MS)).as(daemon.output()).isTrue();

            try (Socket ranges = new Socket("127.0.0.1", ports[1]); Socket motion = new Socket("127.0.0.1", ports[2])) {
                ranges.setSoTimeout(15_000);
                motion.setSoTimeout(15_000);
                BufferedReader rangesIn = reader(ranges);
                JsonNode hello = JSON.readTree(rangesIn.readLine());
                assertThat(hello.path("socket").asText()).isEqualTo("ranges");
                assertThat(hello.path("direction").asText()).isEqualTo("out");

                JsonNode first = nextSample(rangesIn);
                assertThat(first.path("value")).hasSize(4);
                // Start at (1, 2) facing +x in a 4 m room; the sensors sit 0.2 m from the centre.
                assertThat(first.path("value").get(0).asDouble()).isCloseTo(2.8, within(0.05));
                assertThat(first.path("value").get(2).asDouble()).isCloseTo(0.8, within(0.05));

                BufferedReader motionIn = reader(motion);
                assertThat(JSON.readTree(motionIn.readLine()).path("direction").asText()).isEqualTo("both");
                // A control program writes forward five times a second until the rover is 0.3 m nearer the wall.
                OutputStream out = motion.getOutputStream();
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                double frontWhileDriving = first.path("value").get(0).asDouble();
                for (int i = 0; frontWhileDriving >= 2.8 - 0.3; i++) {
                    assertThat(System.nanoTime()).as("the rover drives towards the wall").isLessThan(end);
                    out.write(("{\"value\":[0.4,0.0],\"id\":" + i + "}\n").getBytes(StandardCharsets.UTF_8));
                    out.flush();
                    Thread.sleep(200); // the client's pace, not a wait for the daemon
                    frontWhileDriving = newestFront(rangesIn);
                }

                // Silent client: the watchdog (1 s) stops the rover, so the range stops changing.
                end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (!status(ports[3]).path("watchdog").path("tripped").asBoolean()) {
                    assertThat(System.nanoTime()).as("the watchdog trips").isLessThan(end);
                    Thread.sleep(50);
                }
                double stopped = newestFront(rangesIn);
                for (int same = 0; same < 5; ) {
                    assertThat(System.nanoTime()).as("the range stops changing").isLessThan(end);
                    double next = nextSample(rangesIn).path("value").get(0).asDouble();
                    same = Math.abs(next - stopped) < 0.005 ? same + 1 : 0;
                    stopped = next;
                }
                assertThat(stopped).as("the rover drove on until the watchdog stopped it").isLessThan(frontWhileDriving);
            }
            assertThat(daemon.terminate(15_000)).as(daemon.output()).isZero();
        } finally {
            rover.destroy();
            rover.waitFor(5, TimeUnit.SECONDS);
        }
    }

    /** The shipped config with its ports moved to free ones. */
    private static ObjectNode onPorts(int robot, int ranges, int motion, int status) throws IOException {
        ObjectNode c = (ObjectNode) JSON.readTree(EXAMPLE.resolve("habla.json").toFile());
        c.remove("$schema");
        ((ObjectNode) c.path("interfaces").get(0)).put("address", "127.0.0.1:" + robot);
        ((ObjectNode) c.path("status")).put("port", status);
        for (JsonNode m : c.path("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", m.path("id").asText().equals("ranges") ? ranges : motion);
            }
        }
        return c;
    }

    /** The front range of the newest sample: the next one, or a later one already received. */
    private static double newestFront(BufferedReader in) throws IOException {
        JsonNode newest = nextSample(in);
        while (in.ready()) {
            JsonNode n = JSON.readTree(in.readLine());
            if (n.path("type").asText().equals("sample")) {
                newest = n;
            }
        }
        return newest.path("value").get(0).asDouble();
    }

    /** The daemon's status snapshot (an empty object if the endpoint does not answer). */
    private static JsonNode status(int port) {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(15_000);
            String line = reader(s).readLine();
            return line == null ? JSON.createObjectNode() : JSON.readTree(line);
        } catch (IOException e) {
            return JSON.createObjectNode();
        }
    }

    private static JsonNode nextSample(BufferedReader in) throws IOException {
        for (int i = 0; i < 1_000; i++) {
            String line = in.readLine();
            assertThat(line).as("the daemon closed the ranges socket").isNotNull();
            JsonNode n = JSON.readTree(line);
            if (n.path("type").asText().equals("sample")) {
                return n;
            }
        }
        throw new AssertionError("no sample in 1000 lines");
    }

    private static BufferedReader reader(Socket s) throws IOException {
        return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
    }

    /** Waits until a process's log has a line starting with {@code prefix}; false after {@code millis}. */
    private static boolean awaitLine(Path log, String prefix, long millis) throws Exception {
        long end = System.nanoTime() + millis * 1_000_000;
        while (System.nanoTime() < end) {
            if (Files.exists(log) && Files.readAllLines(log).stream().anyMatch(l -> l.startsWith(prefix))) {
                return true;
            }
            Thread.sleep(50);
        }
        return false;
    }

    private static String log(Path dir, String name) {
        try {
            return Files.readString(dir.resolve(name));
        } catch (IOException e) {
            return "(no log)";
        }
    }
}
