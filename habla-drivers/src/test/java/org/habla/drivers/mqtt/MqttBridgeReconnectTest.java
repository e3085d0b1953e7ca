package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Path;
import java.util.function.Predicate;
import org.habla.daemon.Daemon;
import org.habla.graph.BridgeLink;
import org.habla.testing.DaemonProcess;
import org.habla.testing.LogLines;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The bridge's connection to a real Mosquitto broker is kept by the engine's reconnecting link, as every link is:
 * its attempts and failures in the status, one log line per outage, and the bridge's {@code reconnect} back-off,
 * under which a broker's host that refuses the connect is tried again after the shortest wait, never after a
 * doubled one.
 */
@Timeout(90)
class MqttBridgeReconnectTest {

    /** Every wait for a state of the bridge gives up after this. */
    private static final long WAIT_MS = 30_000;
    /** Failed attempts to see while the broker is away: with a doubling wait they would take hours. */
    private static final int REFUSED_ATTEMPTS = 15;

    @Test
    void aBrokerRestartIsSurvivedWithTheEnginesBackOffCountedAndLoggedOnce(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (Mosquitto broker = Mosquitto.start(tmp); LogLines log = new LogLines(BridgeLink.class);
                Daemon daemon = BridgeRoom.start(BridgeRoom.config(broker, ports, "", "",
                        ", \"reconnect\": {\"initialMs\": 100, \"maxMs\": 3600000}"))) {
            BridgeRoom.awaitOnline(broker);
            JsonNode up = await(daemon, b -> b.path("connected").asBoolean(), "the bridge connected");
            assertThat(up.path("connects").asLong()).isEqualTo(1);
            assertThat(up.path("failures").asLong()).isZero();

            broker.stop();
            // Each attempt is refused by the broker's host: tried again after initialMs (100 ms), so many attempts
            // come while a doubling wait up to maxMs (an hour) would have made only a handful.
            JsonNode down = await(daemon, b -> b.path("failures").asLong() >= REFUSED_ATTEMPTS,
                    REFUSED_ATTEMPTS + " failed attempts");
            assertThat(down.path("connected").asBoolean()).isFalse();
            assertThat(down.path("lastError").asText()).contains("connecting to the broker at " + broker.address(),
                    "refused");
            assertThat(log.at(Level.WARN)).as("one line for the outage, not one per attempt").singleElement()
                    .asString().startsWith("bridge home down: ");

            broker.startAgain();
            BridgeRoom.awaitOnline(broker);
            JsonNode back = await(daemon, b -> b.path("connected").asBoolean(), "the bridge connected again");
            assertThat(back.path("connects").asLong()).isEqualTo(2);
            assertThat(back.has("lastError")).as("cleared once connected").isFalse();
            assertThat(log.at(Level.INFO)).anySatisfy(l -> assertThat(l).startsWith("bridge home up again after"));
        }
    }

    /** The bridge's status once {@code state} holds, polled (bounded by {@link #WAIT_MS}). */
    private static JsonNode await(Daemon daemon, Predicate<JsonNode> state, String what) throws InterruptedException {
        long until = System.nanoTime() + WAIT_MS * 1_000_000L;
        JsonNode b = daemon.status().path("bridges").get(0);
        while (!state.test(b)) {
            if (System.nanoTime() > until) {
                throw new AssertionError("not within " + WAIT_MS + " ms: " + what + "; the bridge: " + b);
            }
            Thread.sleep(20);
            b = daemon.status().path("bridges").get(0);
        }
        return b;
    }
}
