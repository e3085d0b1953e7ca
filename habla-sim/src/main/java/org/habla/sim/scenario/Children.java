package org.habla.sim.scenario;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.habla.cli.DaemonJvm;

/**
 * The separate processes of a scenario — the simulated robot, the daemon, the control program — each
 * with its output in a log file. Closing stops them in the reverse order of their start: SIGTERM, then
 * a kill after a grace period. A shutdown hook does the same if the runner itself is interrupted.
 */
final class Children implements AutoCloseable {

    /** One started process. */
    record Child(String name, Process process, Path log) {
        boolean alive() {
            return process.isAlive();
        }

        /** Waits until this child listens on {@code port} on loopback; fails if it stops first or the time runs out. */
        void awaitPort(int port, long timeoutMs) throws IOException, InterruptedException {
            long end = System.nanoTime() + timeoutMs * 1_000_000L;
            while (System.nanoTime() < end) {
                if (!alive()) {
                    throw new IOException("the " + name + " stopped (exit " + process.exitValue() + "); see " + log);
                }
                try (Socket s = new Socket()) {
                    s.connect(new InetSocketAddress("127.0.0.1", port), CONNECT_MILLIS);
                    return;
                } catch (IOException e) {
                    Thread.sleep(RETRY_MILLIS);
                }
            }
            throw new IOException("port " + port + " did not open within " + timeoutMs + " ms; see " + log);
        }
    }

    /** How long one attempt to connect to a child's port may take, and the wait before the next. */
    private static final int CONNECT_MILLIS = 500;
    private static final long RETRY_MILLIS = 200;

    private final List<Child> children = new ArrayList<>();
    private final Thread hook = new Thread(this::close, "habla-scenario-stop");

    Children() {
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Starts a process with its standard output and error appended to {@code log}. */
    synchronized Child start(String name, List<String> command, Path workDir, Path log) throws IOException {
        return start(name, command, java.util.Map.of(), workDir, log);
    }

    /** Starts a process with these environment variables added to this one's. */
    synchronized Child start(String name, List<String> command, java.util.Map<String, String> env, Path workDir, Path log)
            throws IOException {
        ProcessBuilder pb = new ProcessBuilder(command).directory(workDir.toFile())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        pb.environment().putAll(env);
        Child c = new Child(name, pb.start(), log);
        children.add(c);
        return c;
    }

    /**
     * The java command that runs {@code habla} in a new JVM with this JVM's classpath; a daemon gets the JVM
     * options the launcher would give it ({@link DaemonJvm}).
     */
    static List<String> habla(String... args) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java));
        String home = System.getProperty("habla.home");
        cmd.addAll(DaemonJvm.options(Path.of(home == null ? "." : home), args[0]));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path")));
        if (home != null) {
            cmd.add("-Dhabla.home=" + home);
        }
        cmd.add("org.habla.cli.Habla");
        cmd.addAll(List.of(args));
        return cmd;
    }

    /** Stops one child: SIGTERM, then a kill after {@code graceMs}. */
    static void stop(Child c, long graceMs) {
        c.process().destroy();
        try {
            if (!c.process().waitFor(graceMs, TimeUnit.MILLISECONDS)) {
                c.process().destroyForcibly().waitFor(2, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            c.process().destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public synchronized void close() {
        for (int i = children.size() - 1; i >= 0; i--) {
            stop(children.get(i), 5_000);
        }
        children.clear();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // already shutting down: this is the hook running
        }
    }
}
