package org.habla.bench;

import java.io.IOException;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;

/**
 * The daemon the socket benchmarks measure, started in this JVM from a real config: a {@code habla}
 * interface to {@link BenchRobot}, then {@code channel} (sensors &amp; actuators) → {@code pass-through}
 * (processing) → {@code pass-through} (virtual, exposed as socket {@code value}). Every input is a
 * queue, so every reading reaches the socket and none is conflated away. The three types are light, so the
 * chain runs on the robot link's reader thread; {@link #startOwnThreads} gives each method a thread of its own
 * ({@code "thread": "own"}), as every method had before light methods ran inline.
 */
final class BenchDaemon {

    private BenchDaemon() {
    }

    static Daemon start(int robotPort) throws IOException, ConfigException {
        return start(robotPort, null);
    }

    /** The same chain, each method on a thread of its own. */
    static Daemon startOwnThreads(int robotPort) throws IOException, ConfigException {
        return start(robotPort, null, false, null, false, null, OWN_THREAD);
    }

    /** What a method's entry gets to run on a thread of its own. */
    private static final String OWN_THREAD = ", \"thread\": \"own\"";

    /** The same, with the processing method placed on the worker {@code host} ({@code host:port}) if not null. */
    static Daemon start(int robotPort, String host) throws IOException, ConfigException {
        return start(robotPort, host, false);
    }

    /** The same, with {@code security} (the config's "security" object, or null): a worker's secret, say. */
    static Daemon start(int robotPort, String host, String security) throws IOException, ConfigException {
        return start(robotPort, host, false, security, false, null);
    }

    /** The same, with the live monitor on a free port if {@code monitor}. */
    static Daemon start(int robotPort, String host, boolean monitor) throws IOException, ConfigException {
        return start(robotPort, host, monitor, null, false, null);
    }

    /**
     * The same, with {@code security} (the config's "security" object, or null) and the socket speaking TLS if
     * {@code tls}; relative files in {@code security} are taken from {@code dir}.
     */
    static Daemon start(int robotPort, String security, boolean tls, java.nio.file.Path dir)
            throws IOException, ConfigException {
        return start(robotPort, null, false, security, tls, dir);
    }

    /**
     * The Pioneer's obstacle chain with its real payloads, from a robot serving {@link BenchRobot.Channels#SONAR}:
     * the sonar method (vector in, range scan out), nearest-distance (scan in, nearest record out) and a virtual
     * relay exposing the nearest record: as many methods and hand-offs as {@link #start(int)}'s chain.
     */
    static Daemon startSonarChain(int robotPort) throws IOException, ConfigException {
        return startSonarChain(robotPort, false);
    }

    /** The same, each method on a thread of its own if {@code ownThreads}. */
    static Daemon startSonarChain(int robotPort, boolean ownThreads) throws IOException, ConfigException {
        String thread = ownThreads ? OWN_THREAD : "";
        int port = DaemonProcess.freePorts(1)[0];
        String json = """
                {"system": "bench", "status": {"port": 0, "monitorPort": 0},
                 "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                                 "params": {"channels": %s}}],
                 "methods": [
                   {"id": "sonar", "type": "sonar", "layer": "sensors_actuators", "inputs": {"ranges": "@robot.sonar"}%s},
                   {"id": "nearest", "type": "nearest-distance", "layer": "processing", "inputs": {"scan": "sonar.scan"}%s},
                   {"id": "v", "type": "pass-through", "layer": "virtual", "inputs": {"in": "nearest.nearest"},
                    "params": {"kind": "record", "delivery": "queue", "capacity": 4096},
                    "expose": {"port": %d, "name": "value"}%s}
                 ]}
                """.formatted(robotPort, BenchRobot.SONAR_CHANNELS_JSON, thread, thread, port, thread);
        PluginRegistry registry = PluginRegistry.discover();
        return Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
    }

    private static Daemon start(int robotPort, String host, boolean monitor, String security, boolean tls,
            java.nio.file.Path dir) throws IOException, ConfigException {
        return start(robotPort, host, monitor, security, tls, dir, "");
    }

    /** @param thread what each method's entry ends with ({@link #OWN_THREAD}, or nothing) */
    private static Daemon start(int robotPort, String host, boolean monitor, String security, boolean tls,
            java.nio.file.Path dir, String thread) throws IOException, ConfigException {
        int[] ports = DaemonProcess.freePorts(2);
        int port = ports[0];
        String relay = "\"params\": {\"kind\": \"number\", \"delivery\": \"queue\", \"capacity\": 4096}" + thread;
        String json = """
                {"system": "bench", "status": {"port": 0, "monitorPort": %d},%s
                 "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                                 "params": {"channels": %s}}],
                 "methods": [
                   {"id": "s", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}, %s},
                   {"id": "p", "type": "pass-through", "layer": "processing", "inputs": {"in": "s.out"}, %s%s},
                   {"id": "v", "type": "pass-through", "layer": "virtual", "inputs": {"in": "p.out"}, %s,
                    "expose": {"port": %d, "name": "value"%s}}
                 ]}
                """.formatted(monitor ? ports[1] : 0,
                        security == null ? "" : " \"security\": " + security + ",", robotPort, BenchRobot.CHANNELS_JSON, relay, relay,
                        host == null ? "" : ", \"host\": \"" + host + "\"", relay, port, tls ? ", \"tls\": true" : "");
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig config = dir == null ? new ConfigLoader(registry).parse(json)
                : new ConfigLoader(registry).parse(json, dir);
        return Daemon.start(config, registry, EngineClock.system());
    }
}
