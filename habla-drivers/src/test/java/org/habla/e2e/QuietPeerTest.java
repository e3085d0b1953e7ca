package org.habla.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.NetworkNamespace;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A quiet peer is not a lost peer. The teacher's keyboard of the docs — {@code nc -l PORT} in a terminal — may
 * say nothing for minutes: its link stays up, its methods stay fresh and {@code nc} keeps running. A peer whose
 * host vanishes without closing (its cable pulled) is still declared lost, by TCP keep-alive.
 */
@Timeout(180)
class QuietPeerTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    /** The teacher's pause: the figure, twenty times what once dropped the link. */
    private static final long SILENCE_MS = 60_000;

    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    @Test
    void theTeachersNcTerminalStaysConnectedThroughAMinuteOfSilenceAndItsNextLineArrivesFresh() throws Exception {
        int[] ports = DaemonProcess.freePorts(2);
        Process nc = startNc(List.of(), "127.0.0.1", ports[0]);
        Daemon daemon = daemon("127.0.0.1", ports[0], ports[1]);
        await(() -> daemon.status().path("interfaces").get(0).path("up").asBoolean(), 20_000, "the keyboard link is up");
        BufferedReader fromDaemon = client(daemon);

        type(nc, "1");
        JsonNode first = nextSample(fromDaemon);
        assertThat(first.path("value").asText()).isEqualTo("1");
        assertThat(first.path("stale").asBoolean()).isFalse();

        // The teacher says nothing for a minute. Meanwhile, every look finds the link up on its first connection.
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(SILENCE_MS);
        while (System.nanoTime() < end) {
            JsonNode link = daemon.status().path("interfaces").get(0);
            assertThat(link.path("up").asBoolean()).as("link up during the silence: %s", link).isTrue();
            assertThat(link.path("connections").get(0).path("connects").asLong()).as("never reconnected").isEqualTo(1);
            assertThat(method(daemon, "keys").path("stale").asBoolean()).as("the reward socket stays fresh").isFalse();
            assertThat(nc.isAlive()).as("the teacher's nc still runs").isTrue();
            Thread.sleep(500);
        }

        type(nc, "0.5");
        JsonNode after = nextSample(fromDaemon);
        assertThat(after.path("value").asText()).isEqualTo("0.5");
        assertThat(after.path("stale").asBoolean()).as("fresh after the silence").isFalse();
        assertThat(daemon.status().path("interfaces").get(0).path("connections").get(0).path("connects").asLong())
                .isEqualTo(1);
        assertThat(nc.isAlive()).isTrue();
    }

    @Test
    void aQuietPeerWhoseHostVanishesWithoutClosingIsDeclaredLost() throws Exception {
        String why = NetworkNamespace.unavailable();
        if (why != null) {
            Assumptions.abort("skipped: " + why);
        }
        NetworkNamespace ns;
        try {
            ns = NetworkNamespace.create();
        } catch (IOException e) {
            Assumptions.abort("skipped: cannot make a network namespace with a veth pair: " + e.getMessage());
            return;
        }
        toClose.add(ns);
        int[] ports = DaemonProcess.freePorts(2);
        Process nc = startNc(ns.wrapper(), ns.address(), ports[0]);
        Daemon daemon = daemon(ns.address(), ports[0], ports[1]);
        await(() -> daemon.status().path("interfaces").get(0).path("up").asBoolean(), 20_000, "the link is up");
        BufferedReader fromDaemon = client(daemon);
        type(nc, "1");
        assertThat(nextSample(fromDaemon).path("value").asText()).isEqualTo("1");

        ns.cutLink();
        long cut = System.nanoTime();
        int keepAliveS = daemon.config().interfaces().get(0).reconnect().tcpKeepAlive().detectionS();
        await(() -> !daemon.status().path("interfaces").get(0).path("up").asBoolean(), 30_000,
                "the link is declared lost");
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - cut);
        JsonNode link = daemon.status().path("interfaces").get(0);
        System.out.printf("quiet peer behind a pulled cable declared lost after %d ms (keep-alive detection %d s): %s%n",
                tookMs, keepAliveS, link.path("connections").get(0).path("lastError").asText());
        assertThat(nc.isAlive()).as("the peer never closed: it is only unreachable").isTrue();
        await(() -> method(daemon, "keys").path("stale").asBoolean(), 5_000, "the reward socket turns stale");
    }

    // ------------------------------------------------------------------ set-up

    /** keys (text-lines) → key (channel) → key-up (pass-through) → keys (pass-through, exposed). */
    private Daemon daemon(String host, int keyboardPort, int socketPort) throws Exception {
        String json = """
                {"system": "quiet-peer-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                 "interfaces": [{"id": "keyboard", "driver": "text-lines", "address": "%s:%d",
                                 "reconnect": {"initialMs": 100, "maxMs": 400}}],
                 "methods": [
                  {"id": "key", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@keyboard.lines"},
                   "params": {"kind": "text"}},
                  {"id": "key-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "key.out"},
                   "params": {"kind": "text", "delivery": "queue"}},
                  {"id": "keys", "type": "pass-through", "layer": "virtual", "inputs": {"in": "key-up.out"},
                   "params": {"kind": "text", "delivery": "queue"}, "expose": {"port": %d, "name": "keys"}}]}
                """.formatted(host, keyboardPort, socketPort);
        PluginRegistry registry = PluginRegistry.discover();
        Daemon d = Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
        toClose.add(d);
        return d;
    }

    /** A control client of the {@code keys} socket, once the daemon has taken it on (its hello came). */
    private BufferedReader client(Daemon daemon) throws IOException {
        Socket s = new Socket("127.0.0.1", daemon.port("keys"));
        s.setSoTimeout(10_000);
        toClose.add(s);
        BufferedReader in = lines(s);
        assertThat(JSON.readTree(in.readLine()).path("type").asText()).isEqualTo("hello");
        return in;
    }

    /** {@code nc -l HOST PORT}, run under {@code wrapper}; its standard input is the teacher's keyboard. */
    private Process startNc(List<String> wrapper, String host, int port) throws IOException {
        Path nc = findOnPath("nc");
        if (nc == null) {
            Assumptions.abort("skipped: nc (netcat-openbsd) is not installed; the docs' teacher terminal needs it");
        }
        List<String> cmd = new ArrayList<>(wrapper);
        cmd.addAll(List.of(nc.toString(), "-l", host, String.valueOf(port)));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .start();
        toClose.add(() -> {
            p.destroy();
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        });
        return p;
    }

    private static Path findOnPath(String name) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
            Path p = Path.of(dir, name);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    private static void type(Process nc, String line) throws IOException {
        OutputStream keys = nc.getOutputStream();
        keys.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        keys.flush();
    }

    private static BufferedReader lines(Socket s) throws IOException {
        return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
    }

    /** The next sample line, skipping the hello and notices (each line within the socket's 10 s). */
    private static JsonNode nextSample(BufferedReader in) throws IOException {
        for (int i = 0; i < 100; i++) {
            String line = in.readLine();
            assertThat(line).as("the socket is open").isNotNull();
            JsonNode n = JSON.readTree(line);
            if (n.path("type").asText().equals("sample")) {
                return n;
            }
        }
        throw new AssertionError("no sample in 100 lines");
    }

    private static JsonNode method(Daemon daemon, String id) {
        for (JsonNode m : daemon.status().path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id);
    }

    private static void await(BooleanSupplier condition, long millis, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting until " + what).isLessThan(end);
            Thread.sleep(20);
        }
    }
}
