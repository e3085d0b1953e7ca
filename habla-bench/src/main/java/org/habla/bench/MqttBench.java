package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.hivemq.client.mqtt.MqttClient;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import java.io.IOException;
import java.nio.file.Files;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;

/**
 * Benchmark (h): what the broker costs. One daemon (robot channel → two pass-throughs → a socket, as in (a)) with
 * an MQTT bridge publishing that socket to a local Mosquitto; a control client on the socket and an MQTT subscriber
 * on the bridge's topic read the same samples in the same window, so the difference of their latencies is the broker
 * round trip added per sample. Then the readings come as fast as the robot can write them, and the subscriber counts
 * what the bridge carried per second (and the bridge what it dropped).
 */
final class MqttBench {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final int rateHz;
    private final int warmupS;
    private final int seconds;

    MqttBench(int rateHz, int warmupS, int seconds) {
        this.rateHz = rateHz;
        this.warmupS = warmupS;
        this.seconds = seconds;
    }

    void run() throws Exception {
        try (Mosquitto broker = Mosquitto.start(Files.createTempDirectory("habla-bench-mqtt"))) {
            System.out.printf("%n(h) the MQTT bridge, Mosquitto %s on loopback%n", version(broker));
            latency(broker);
            throughput(broker);
        }
    }

    private void latency(Mosquitto broker) throws Exception {
        System.out.printf("latency, robot stamp -> reader, %d Hz readings, %d s warm-up, %d s measured%n", rateHz,
                warmupS, seconds);
        System.out.printf("%-44s %8s %8s %8s %8s %8s %8s%n", "path", "samples", "lost", "p50 µs", "p90 µs", "p99 µs",
                "max µs");
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz); Daemon d = daemon(robot.port(), broker);
                SampleClient socket = new SampleClient(d.port("value")); Subscriber mqtt = new Subscriber(broker)) {
            LatencyBench.await(() -> socket.total() > 0 && mqtt.total() > 0, 20_000, "no sample reached both readers");
            Thread.sleep(warmupS * 1000L);
            socket.startRecording();
            mqtt.startRecording();
            Thread.sleep(seconds * 1000L);
            socket.stopRecording();
            mqtt.stopRecording();
            Histogram direct = socket.latencyMicros();
            Histogram bridged = mqtt.latencyMicros();
            row("daemon socket (direct)", socket.samples(), socket.missing(), direct);
            row("MQTT bridge -> Mosquitto -> subscriber", mqtt.samples(), mqtt.missing(), bridged);
            System.out.printf("broker round trip added per sample: p50 %d µs, p90 %d µs, p99 %d µs%n",
                    bridged.getValueAtPercentile(50) - direct.getValueAtPercentile(50),
                    bridged.getValueAtPercentile(90) - direct.getValueAtPercentile(90),
                    bridged.getValueAtPercentile(99) - direct.getValueAtPercentile(99));
        }
    }

    private void throughput(Mosquitto broker) throws Exception {
        System.out.printf("throughput, readings as fast as the robot writes them, %d s warm-up, %d s measured%n",
                warmupS, seconds);
        try (BenchRobot robot = new BenchRobot(0); Daemon d = daemon(robot.port(), broker);
                SampleClient socket = new SampleClient(d.port("value")); Subscriber mqtt = new Subscriber(broker)) {
            LatencyBench.await(() -> mqtt.total() > 0, 20_000, "no sample reached the subscriber");
            Thread.sleep(warmupS * 1000L);
            long sent0 = robot.sent();
            long socket0 = socket.total();
            long mqtt0 = mqtt.total();
            JsonNode b0 = d.status().path("bridges").get(0);
            Thread.sleep(seconds * 1000L);
            long sent = robot.sent() - sent0;
            long viaSocket = socket.total() - socket0;
            long viaMqtt = mqtt.total() - mqtt0;
            JsonNode b1 = d.status().path("bridges").get(0);
            System.out.printf("%-44s %12s%n", "path", "samples/s");
            System.out.printf("%-44s %12.0f%n", "robot readings written", sent / (double) seconds);
            System.out.printf("%-44s %12.0f%n", "daemon socket (direct)", viaSocket / (double) seconds);
            System.out.printf("%-44s %12.0f%n", "MQTT bridge -> Mosquitto -> subscriber", viaMqtt / (double) seconds);
            System.out.printf("bridge in the window: %d published, %d dropped (more than %d on their way, or the broker "
                    + "away)%n", b1.path("published").asLong() - b0.path("published").asLong(),
                    b1.path("dropped").asLong() - b0.path("dropped").asLong(), 4096);
        }
    }

    private static void row(String name, long samples, long missing, Histogram h) {
        System.out.printf("%-44s %8d %8d %8d %8d %8d %8d%n", name, samples, missing, h.getValueAtPercentile(50),
                h.getValueAtPercentile(90), h.getValueAtPercentile(99), h.getMaxValue());
    }

    private static Daemon daemon(int robotPort, Mosquitto broker) throws Exception {
        int port = DaemonProcess.freePorts(1)[0];
        String relay = "\"params\": {\"kind\": \"number\", \"delivery\": \"queue\", \"capacity\": 4096}";
        String json = """
                {"system": "bench", "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                                 "params": {"channels": %s}}],
                 "methods": [
                   {"id": "s", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}, %s},
                   {"id": "p", "type": "pass-through", "layer": "processing", "inputs": {"in": "s.out"}, %s},
                   {"id": "v", "type": "pass-through", "layer": "virtual", "inputs": {"in": "p.out"}, %s,
                    "expose": {"port": %d, "name": "value"}}],
                 "bridges": [{"id": "bench", "type": "mqtt", "address": "%s",
                              "params": {"publish": ["value"], "discovery": false}}]}
                """.formatted(robotPort, BenchRobot.CHANNELS_JSON, relay, relay, relay, port, broker.address());
        PluginRegistry registry = PluginRegistry.discover();
        return Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
    }

    private static String version(Mosquitto broker) {
        try {
            Process p = new ProcessBuilder(Mosquitto.BROKER.toString(), "-h").redirectErrorStream(true).start();
            String first = new String(p.getInputStream().readNBytes(200)).lines().findFirst().orElse("");
            p.waitFor(5, TimeUnit.SECONDS);
            return first.replaceAll(".*version ", "").trim();
        } catch (IOException | InterruptedException e) {
            return "?";
        }
    }

    /** An MQTT subscriber on the bridge's topic, measuring each sample's age from its source time. */
    private static final class Subscriber implements AutoCloseable {
        private final Mqtt5AsyncClient client;
        private final Histogram latencyMicros = new Histogram(60_000_000L, 3);
        private final EngineClock clock = EngineClock.system();
        private volatile long total;
        private boolean recording;
        private long samples;
        private long missing;
        private long lastSeq = -1;

        Subscriber(Mosquitto broker) throws Exception {
            client = MqttClient.builder().useMqttVersion5().identifier("bench-subscriber").serverHost("127.0.0.1")
                    .serverPort(broker.port()).buildAsync();
            client.publishes(MqttGlobalPublishFilter.SUBSCRIBED, p -> take(p.getPayloadAsBytes()));
            client.connect().get(10, TimeUnit.SECONDS);
            client.subscribeWith().topicFilter("habla/bench/value").qos(MqttQos.AT_MOST_ONCE).send()
                    .get(10, TimeUnit.SECONDS);
        }

        private void take(byte[] payload) {
            try {
                JsonNode n = JSON.readTree(payload);
                long age = clock.nowMicros() - n.path("t").asLong();
                long seq = n.path("seq").asLong();
                total++;
                synchronized (this) {
                    if (recording) {
                        latencyMicros.recordValue(Math.max(0, Math.min(age, latencyMicros.getHighestTrackableValue())));
                        samples++;
                        if (lastSeq >= 0 && seq > lastSeq + 1) {
                            missing += seq - lastSeq - 1;
                        }
                    }
                    lastSeq = seq;
                }
            } catch (IOException e) {
                // not a sample line
            }
        }

        long total() {
            return total;
        }

        synchronized void startRecording() {
            latencyMicros.reset();
            samples = 0;
            missing = 0;
            recording = true;
        }

        synchronized void stopRecording() {
            recording = false;
        }

        synchronized Histogram latencyMicros() {
            return latencyMicros.copy();
        }

        synchronized long samples() {
            return samples;
        }

        synchronized long missing() {
            return missing;
        }

        @Override
        public void close() {
            client.disconnect();
        }
    }
}
