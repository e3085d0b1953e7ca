package org.habla.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A Linux network namespace of its own, joined to this one by a veth pair: this side has
 * {@code 10.231.K.1/24}, the namespace {@code 10.231.K.2/24}, so a process started in it (with
 * {@link #wrapper()}) is reached at {@link #address()} as another computer would be. Needs root and
 * {@code ip}; {@link #create} says why when it cannot, so a test can skip with the reason.
 */
public final class NetworkNamespace implements AutoCloseable {

    private final String name;
    private final int subnet;
    private final String inside;
    private final String outside;

    private NetworkNamespace(String name, int subnet, String inside, String outside) {
        this.name = name;
        this.subnet = subnet;
        this.inside = inside;
        this.outside = outside;
    }

    /** Why a namespace cannot be made here, or null when it can. */
    public static String unavailable() {
        if (!"root".equals(System.getProperty("user.name"))) {
            return "network namespaces need root (running as " + System.getProperty("user.name") + ")";
        }
        try {
            run("ip", "netns", "list");
            return null;
        } catch (IOException e) {
            return "'ip netns' is not usable: " + e.getMessage();
        }
    }

    /** Makes a namespace with its veth pair and addresses; removes what it made if a step fails. */
    public static NetworkNamespace create() throws IOException {
        long id = ProcessHandle.current().pid() % 100_000;
        int subnet = (int) (ProcessHandle.current().pid() % 200) + 20 + (int) (System.nanoTime() % 30);
        String name = "habla-" + id + "-" + subnet;
        String outside = "hb" + id + "o" + subnet;
        String inside = "hb" + id + "i" + subnet;
        NetworkNamespace ns = new NetworkNamespace(name, subnet, inside, outside);
        try {
            run("ip", "netns", "add", name);
            run("ip", "link", "add", outside, "type", "veth", "peer", "name", inside);
            run("ip", "link", "set", inside, "netns", name);
            run("ip", "addr", "add", "10.231." + subnet + ".1/24", "dev", outside);
            run("ip", "link", "set", outside, "up");
            run("ip", "netns", "exec", name, "ip", "addr", "add", ns.address() + "/24", "dev", inside);
            run("ip", "netns", "exec", name, "ip", "link", "set", inside, "up");
            run("ip", "netns", "exec", name, "ip", "link", "set", "lo", "up");
        } catch (IOException e) {
            ns.close();
            try {
                run("ip", "link", "del", outside);
            } catch (IOException ignored) {
                // it went with the namespace, or was never made
            }
            throw e;
        }
        return ns;
    }

    /** The namespace's own address. */
    public String address() {
        return "10.231." + subnet + ".2";
    }

    /** This side's address on the veth pair. */
    public String hostAddress() {
        return "10.231." + subnet + ".1";
    }

    /** The command prefix that runs a program inside the namespace. */
    public List<String> wrapper() {
        return List.of("ip", "netns", "exec", name);
    }

    /**
     * Takes the namespace's end of the veth pair down, as if its cable were pulled: its processes keep running
     * and keep their sockets, but nothing reaches them and nothing of theirs comes out — no FIN, no reset.
     */
    public void cutLink() throws IOException {
        run("ip", "netns", "exec", name, "ip", "link", "set", inside, "down");
    }

    /**
     * Deletes the namespace and the veth pair. The pair is deleted by name too: a socket of the namespace still
     * closing (its FIN unanswered behind a cut link) keeps the namespace alive for minutes, and with it the pair.
     */
    @Override
    public void close() {
        try {
            run("ip", "netns", "del", name);
        } catch (IOException e) {
            System.err.println("could not delete network namespace " + name + ": " + e.getMessage());
        }
        try {
            run("ip", "link", "del", outside);
        } catch (IOException e) {
            // gone with the namespace
        }
    }

    private static void run(String... cmd) throws IOException {
        Process p = new ProcessBuilder(new ArrayList<>(List.of(cmd))).redirectErrorStream(true).start();
        try {
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException(String.join(" ", cmd) + " did not finish in 10 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        if (p.exitValue() != 0) {
            throw new IOException(String.join(" ", cmd) + " failed: "
                    + new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip());
        }
    }
}
