package org.habla.testing;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs {@code habla ...} in a JVM of its own, as a user would, with this test's class path; its
 * output goes to a log file the test can read. Every wait is bounded.
 */
public final class DaemonProcess implements AutoCloseable {

    private final Process process;
    private final Path log;

    private DaemonProcess(Process process, Path log) {
        this.process = process;
        this.log = log;
    }

    /** Starts {@code habla args...}; output (stdout and stderr) goes to {@code log}. */
    public static DaemonProcess start(Path log, String... args) throws IOException {
        return startWrapped(List.of(), log, args);
    }

    /**
     * Starts {@code habla args...} under a wrapper command, e.g. {@code ip netns exec NAME} to run it in a
     * network namespace; output goes to {@code log}.
     */
    public static DaemonProcess startWrapped(List<String> wrapper, Path log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(wrapper);
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx512m");
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add("org.habla.cli.Habla");
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        return new DaemonProcess(p, log);
    }

    /**
     * How long a test lets a new JVM take to open its first port: a second on a quiet machine, but one load test in
     * five (fresh clones, busy processes on both cores) saw a simulator print nothing for 20 s.
     */
    public static final long START_MS = 60_000;

    /** Waits until a TCP port on loopback accepts connections; false after {@code millis}. */
    public static boolean awaitPort(int port, long millis) throws InterruptedException {
        return awaitPort("127.0.0.1", port, millis);
    }

    /** Waits until {@code host:port} accepts connections; false after {@code millis}. */
    public static boolean awaitPort(String host, int port, long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (System.nanoTime() < end) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress(host, port), 200);
                return true;
            } catch (IOException e) {
                Thread.sleep(50);
            }
        }
        return false;
    }

    /**
     * Ports this JVM has handed out: never handed out again. The kernel gives a port just closed to the next bind
     * of port 0 as readily as any other, so a test that took five ports for its daemon and then started a broker on
     * "a free port" had the broker on one of the daemon's ports (one suite run in five beside busy processes).
     */
    private static final java.util.Set<Integer> HANDED_OUT = java.util.concurrent.ConcurrentHashMap.newKeySet();
    /** How many ports one call may look at before it gives up. */
    private static final int LOOKS_PER_PORT = 200;

    /**
     * {@code n} distinct free loopback ports that no earlier call in this JVM returned. Each is free when returned
     * and reserved against this JVM's later calls ({@link Mosquitto} takes its port here too); another process may
     * still take one before the test binds it.
     */
    public static int[] freePorts(int n) throws IOException {
        int[] ports = new int[n];
        List<ServerSocket> held = new ArrayList<>();
        try {
            int found = 0;
            for (int look = 0; found < n; look++) {
                if (look >= LOOKS_PER_PORT * n) {
                    throw new IOException("no free port that this JVM had not handed out after " + look + " tries");
                }
                ServerSocket s = new ServerSocket(0);
                held.add(s); // held until the end, so the kernel does not give the same port again in this loop
                if (HANDED_OUT.add(s.getLocalPort())) {
                    ports[found++] = s.getLocalPort();
                }
            }
        } finally {
            for (ServerSocket s : held) {
                s.close();
            }
        }
        return ports;
    }

    /** Whether ::1 can be bound here (a container may have IPv6 off). */
    public static boolean ipv6Loopback() {
        try (ServerSocket s = new ServerSocket()) {
            s.bind(new InetSocketAddress(java.net.InetAddress.getByName("::1"), 0));
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    public boolean alive() {
        return process.isAlive();
    }

    /** The process's output so far. */
    public String output() {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return "(no output: " + e.getMessage() + ")";
        }
    }

    /** Sends SIGTERM and waits for the exit code; -1 if it did not exit within {@code millis}. */
    public int terminate(long millis) throws InterruptedException {
        process.destroy();
        if (!process.waitFor(millis, TimeUnit.MILLISECONDS)) {
            return -1;
        }
        return process.exitValue();
    }

    /** Waits for the process to end by itself; -1 after {@code millis}. */
    public int waitFor(long millis) throws InterruptedException {
        if (!process.waitFor(millis, TimeUnit.MILLISECONDS)) {
            return -1;
        }
        return process.exitValue();
    }

    @Override
    public void close() {
        process.destroyForcibly();
        try {
            process.waitFor(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
