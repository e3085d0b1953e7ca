package org.habla.daemon;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import ch.qos.logback.classic.Level;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import org.habla.config.ConfigError;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The daemon's one hook for the products beside it: every {@link DaemonExtension} on the class path starts once the
 * daemon's own ports are bound, reads it through {@link LiveGraph}, and stops with it; one whose port is taken stops
 * the start.
 */
@Timeout(60)
class DaemonExtensionTest {

    private static final int CONNECT_MILLIS = 2_000;
    /** What the extension saw when the daemon started it; set by {@link Probe}. */
    static volatile boolean controlPortBound;
    static volatile String systemSeen;
    static final AtomicBoolean CLOSED = new AtomicBoolean();
    static volatile boolean refuse;

    private final ClassLoader original = Thread.currentThread().getContextClassLoader();

    /** The extension under test: it records what it sees and can refuse its port. */
    public static final class Probe implements DaemonExtension {

        @Override
        public Optional<Running> start(HablaConfig config, PluginRegistry registry, LiveGraph daemon)
                throws IOException {
            if (refuse) {
                throw new PortsUnavailableException(List.of(new ConfigError("$.status.probePort", "taken")));
            }
            int port = config.methods().get(0).expose().orElseThrow().port();
            controlPortBound = connects(port);
            systemSeen = daemon.status().path("system").asText();
            return Optional.of(new Running("probe", 0, "probe", () -> CLOSED.set(true)));
        }
    }

    @AfterEach
    void restoreTheClassLoader() {
        Thread.currentThread().setContextClassLoader(original);
        refuse = false;
    }

    @Test
    void anExtensionStartsOnceTheControlSocketsAreBoundReadsTheDaemonAndStopsWithIt(@TempDir Path dir)
            throws Exception {
        withTheProbe(dir);
        int port = DaemonProcess.freePorts(1)[0];
        CLOSED.set(false);
        try (Daemon d = daemon(port, 0)) {
            assertThat(controlPortBound).as("the control socket was bound when the extension started").isTrue();
            assertThat(systemSeen).isEqualTo("hooked");
            assertThat(d.extensionPort("probe")).isZero();
            assertThat(CLOSED).isFalse();
        }
        assertThat(CLOSED).as("closed with the daemon").isTrue();
    }

    @Test
    void anExtensionWhosePortIsTakenStopsTheStartAndFreesTheDaemonsPorts(@TempDir Path dir) throws Exception {
        withTheProbe(dir);
        refuse = true;
        int port = DaemonProcess.freePorts(1)[0];
        PortsUnavailableException e = catchThrowableOfType(PortsUnavailableException.class, () -> daemon(port, 0));
        assertThat(e.errors()).extracting(ConfigError::path).containsExactly("$.status.probePort");
        assertThat(connects(port)).as("the control socket is closed again").isFalse();
    }

    @Test
    void aMonitorPortWithNoMonitorOnTheClassPathIsSaidAndTheDaemonRunsWithoutIt() throws Exception {
        int[] ports = DaemonProcess.freePorts(2);
        try (LogLines log = new LogLines(Daemon.class); Daemon d = daemon(ports[0], ports[1])) {
            assertThat(d.extensionPort(Daemon.MONITOR)).isZero();
            assertThat(log.at(Level.WARN)).anySatisfy(l -> assertThat(l)
                    .contains("status.monitorPort is " + ports[1], "no monitor is on this class path"));
        }
    }

    /** Makes {@link Probe} the one extension the daemon finds, through a services file of the context class loader. */
    private void withTheProbe(Path dir) throws IOException {
        Path services = Files.createDirectories(dir.resolve("META-INF/services"));
        Files.writeString(services.resolve(DaemonExtension.class.getName()), Probe.class.getName() + "\n");
        Thread.currentThread().setContextClassLoader(new URLClassLoader(new URL[] {dir.toUri().toURL()}, original));
    }

    private static Daemon daemon(int controlPort, int monitorPort) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        String json = """
                {"system": "hooked", "safety": {"watchdogMs": 0}, "status": {"port": 0, "monitorPort": %d},
                 "methods": [{"id": "cmd", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                              "params": {"kind": "number"}, "expose": {"port": %d}}]}
                """.formatted(monitorPort, controlPort);
        return Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
    }

    private static boolean connects(int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), CONNECT_MILLIS);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
