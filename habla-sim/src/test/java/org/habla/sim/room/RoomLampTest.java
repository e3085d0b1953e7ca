package org.habla.sim.room;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.function.Predicate;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A lamp of config/room.json whose command was dropped on the way (the lamp offline, the broker gone) gets it as
 * soon as it can be reached, and a lamp switched at the wall is seen: a real Mosquitto broker, and
 * {@code mosquitto_pub}/{@code mosquitto_sub} as the kitchen lamp.
 */
@Timeout(120)
class RoomLampTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String LAMP = "zigbee2mqtt/kitchen_lamp";

    @Test
    void aLampCommandDroppedWhileTheLampOrTheBrokerWasAwayIsSentOnceItIsBack(@TempDir Path tmp) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp);
                Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(
                        RoomEndToEndTest.roomConfig(broker.port(), ports)), registry, EngineClock.system());
                Socket action = new Socket("127.0.0.1", ports[4])) {
            action.setSoTimeout(30_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(action.getInputStream(), StandardCharsets.UTF_8));
            OutputStream out = action.getOutputStream();
            await(daemon, "the link up", s -> s.path("up").asBoolean());

            // The lamp is offline: the command is dropped and counted.
            broker.publish(LAMP + "/availability", "{\"state\":\"offline\"}", true);
            await(daemon, "the lamp unavailable", s -> s.path("unavailable").has("kitchen_lamp_state"));
            write(in, out, "kitchen 0.8", 1);
            await(daemon, "the command dropped", s -> s.path("commandsDropped").asLong() == 1);

            // It is back: the same action reaches it.
            broker.publish(LAMP + "/availability", "{\"state\":\"online\"}", true);
            await(daemon, "the lamp available", s -> !s.path("unavailable").has("kitchen_lamp_state"));
            assertThat(sentOnWrite(broker, in, out, "kitchen 0.8", 2)).isEqualTo("{\"state\":\"ON\",\"brightness\":203}");
            broker.publish(LAMP, "{\"state\":\"ON\",\"brightness\":203,\"linkquality\":120}", false);

            // The broker goes away: dropped again, and sent when it is back.
            broker.stop();
            await(daemon, "the link down", s -> !s.path("up").asBoolean());
            write(in, out, "kitchen 0.5", 3);
            await(daemon, "the command dropped", s -> s.path("commandsDropped").asLong() == 2);
            broker.startAgain();
            await(daemon, "the link up again", s -> s.path("up").asBoolean());
            assertThat(sentOnWrite(broker, in, out, "kitchen 0.5", 4)).isEqualTo("{\"state\":\"ON\",\"brightness\":127}");

            // Switched off at the wall: the lamp says so, and the same action lights it again.
            broker.publish(LAMP, "{\"state\":\"ON\",\"brightness\":127}", false);
            broker.publish(LAMP, "{\"state\":\"OFF\",\"brightness\":0}", false);
            assertThat(sentOnWrite(broker, in, out, "kitchen 0.5", 5)).isEqualTo("{\"state\":\"ON\",\"brightness\":127}");
        }
    }

    /**
     * Writes an action until the lamp's /set topic carries something (what the lamp said last may still be on its
     * way to the daemon), and returns the first message there (bounded).
     */
    private static String sentOnWrite(Mosquitto broker, BufferedReader in, OutputStream out, String text, int id)
            throws Exception {
        broker.publish("ready/" + id, "yes", true);
        Process sub = broker.subscriber("-t", "ready/" + id, "-t", LAMP + "/set", "-C", "2", "-W", "30");
        try (BufferedReader seen = new BufferedReader(new InputStreamReader(sub.getInputStream(),
                StandardCharsets.UTF_8))) {
            assertThat(seen.readLine()).as("the lamp listens").isEqualTo("yes");
            for (int i = 0; i < 100 && sub.isAlive(); i++) {
                write(in, out, text, id * 1000 + i);
                sub.waitFor(100, java.util.concurrent.TimeUnit.MILLISECONDS);
            }
            return seen.readLine();
        } finally {
            sub.destroyForcibly();
        }
    }

    private static void write(BufferedReader in, OutputStream out, String text, int id) throws Exception {
        out.write(("{\"value\": \"" + text + "\", \"id\": " + id + "}\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
        for (int i = 0; i < 10_000; i++) {
            JsonNode n = JSON.readTree(in.readLine());
            if (n.path("id").asInt() == id) {
                assertThat(n.path("type").asText()).as(n.toString()).isEqualTo("ok");
                return;
            }
        }
        throw new AssertionError("no answer to action " + id);
    }

    /** Waits (bounded) until the room interface's status satisfies {@code condition}. */
    private static void await(Daemon daemon, String what, Predicate<JsonNode> condition) throws InterruptedException {
        long until = System.nanoTime() + 30_000_000_000L;
        while (!condition.test(daemon.status().path("interfaces").get(0))) {
            if (System.nanoTime() > until) {
                throw new AssertionError("not " + what + " within 30 s: " + daemon.status().path("interfaces").get(0));
            }
            Thread.sleep(10);
        }
    }
}
