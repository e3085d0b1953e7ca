package org.habla.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A real Mosquitto broker for a test, on a free loopback port, with no persistence: start it, stop it, start it
 * again on the same port (a broker restart), read its log. The Debian packages {@code mosquitto} and
 * {@code mosquitto-clients} are installed with apt-get when they are missing, as {@code .ci/run} does on a fresh
 * machine. Every wait is bounded.
 */
public final class Mosquitto implements AutoCloseable {

    /** Where Debian puts the broker. */
    public static final Path BROKER = Path.of("/usr/sbin/mosquitto");
    private static final long READY_MILLIS = 10_000;

    private final Path dir;
    private final int port;
    private final List<String> listenerLines;
    private final boolean anonymous;
    private Process process;

    private Mosquitto(Path dir, int port, List<String> listenerLines, boolean anonymous) {
        this.dir = dir;
        this.port = port;
        this.listenerLines = List.copyOf(listenerLines);
        this.anonymous = anonymous;
    }

    /** Starts a broker on a free loopback port that lets anyone in; its config and log live in {@code dir}. */
    public static Mosquitto start(Path dir) throws IOException, InterruptedException {
        return start(dir, List.of(), true);
    }

    /**
     * Starts a broker on a free loopback port whose listener has {@code listenerLines} too (e.g. {@code cafile},
     * {@code certfile}, {@code keyfile}, {@code password_file}), letting anonymous clients in or not.
     */
    public static Mosquitto start(Path dir, List<String> listenerLines, boolean anonymous)
            throws IOException, InterruptedException {
        ensureInstalled();
        IOException last = null;
        for (int attempt = 0; attempt < 3; attempt++) {
            Mosquitto m = new Mosquitto(dir, freePort(), listenerLines, anonymous);
            try {
                m.startAgain();
                return m;
            } catch (IOException e) {
                last = e;
                m.close();
            }
        }
        throw last;
    }

    public int port() {
        return port;
    }

    /** {@code 127.0.0.1:port}, as a config's address. */
    public String address() {
        return "127.0.0.1:" + port;
    }

    /** Starts the broker again on the same port after {@link #stop()}. */
    public void startAgain() throws IOException, InterruptedException {
        Path conf = dir.resolve("mosquitto-" + port + ".conf");
        List<String> lines = new java.util.ArrayList<>(List.of("listener " + port + " 127.0.0.1"));
        lines.addAll(listenerLines);
        lines.addAll(List.of("allow_anonymous " + anonymous, "persistence false", "log_dest stderr", "log_type error",
                "log_type warning", "log_type notice", ""));
        Files.writeString(conf, String.join("\n", lines));
        process = new ProcessBuilder(BROKER.toString(), "-c", conf.toString()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log().toFile())).start();
        long end = System.nanoTime() + READY_MILLIS * 1_000_000L;
        while (process.isAlive() && System.nanoTime() < end) {
            if (DaemonProcess.awaitPort(port, 200)) {
                return;
            }
        }
        stop();
        throw new IOException("mosquitto did not listen on port " + port + " within " + READY_MILLIS
                + " ms; its log: " + Files.readString(log()));
    }

    /** Kills the broker (its clients see the connection drop) and waits for it to end. */
    public void stop() throws InterruptedException {
        Process p = process;
        if (p != null && p.isAlive()) {
            p.destroy();
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
            }
        }
    }

    public Path log() {
        return dir.resolve("mosquitto-" + port + ".log");
    }

    /**
     * Runs a Mosquitto client ({@code mosquitto_pub}, {@code mosquitto_sub}) against this broker and returns its
     * output; {@code args} follow {@code -h 127.0.0.1 -p PORT}. Fails if it runs longer than {@code millis}.
     */
    public String client(long millis, String tool, String... args) throws IOException, InterruptedException {
        List<String> cmd = new java.util.ArrayList<>(List.of(tool, "-h", "127.0.0.1", "-p", Integer.toString(port)));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        if (!p.waitFor(millis, TimeUnit.MILLISECONDS)) {
            p.destroyForcibly();
            throw new IOException(String.join(" ", cmd) + " ran longer than " + millis + " ms");
        }
        return new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
    }

    /** Publishes one message with {@code mosquitto_pub} (not retained unless {@code retain}). */
    public void publish(String topic, String payload, boolean retain) throws IOException, InterruptedException {
        String out = retain ? client(10_000, "mosquitto_pub", "-t", topic, "-m", payload, "-r")
                : client(10_000, "mosquitto_pub", "-t", topic, "-m", payload);
        if (!out.isBlank()) {
            throw new IOException("mosquitto_pub: " + out);
        }
    }

    /** Starts {@code mosquitto_sub} in the background; the caller reads its output and destroys it. */
    public Process subscriber(String... args) throws IOException {
        List<String> cmd = new java.util.ArrayList<>(List.of("mosquitto_sub", "-h", "127.0.0.1", "-p",
                Integer.toString(port)));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true).start();
    }

    @Override
    public void close() throws InterruptedException {
        stop();
    }

    /** A free port no other caller in this JVM was given ({@link DaemonProcess#freePorts}). */
    private static int freePort() throws IOException {
        return DaemonProcess.freePorts(1)[0];
    }

    private static synchronized void ensureInstalled() throws IOException, InterruptedException {
        if (Files.isExecutable(BROKER) && Files.isExecutable(Path.of("/usr/bin/mosquitto_pub"))) {
            return;
        }
        Process p = new ProcessBuilder("sh", "-c", "(apt-get install -y --no-install-recommends mosquitto "
                + "mosquitto-clients || (apt-get update && apt-get install -y --no-install-recommends mosquitto "
                + "mosquitto-clients))").redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        if (!p.waitFor(5, TimeUnit.MINUTES) || !Files.isExecutable(BROKER)) {
            throw new IOException("Mosquitto is not installed and apt-get could not install it (run as root: "
                    + "apt-get install mosquitto mosquitto-clients): " + out);
        }
    }
}
