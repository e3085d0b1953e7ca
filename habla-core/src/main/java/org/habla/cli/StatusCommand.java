package org.habla.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code habla status}: reads a running daemon's status endpoint and prints it as tables (or JSON). */
@Command(name = "status", mixinStandardHelpOptions = true,
        description = "Show a running daemon's methods, links, sockets and the watchdog.")
public final class StatusCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--host", defaultValue = "127.0.0.1", description = "The daemon's host (default ${DEFAULT-VALUE}).")
    private String host;

    @Option(names = "--port", defaultValue = "7099", description = "The status port (default ${DEFAULT-VALUE}).")
    private int port;

    @Option(names = "--json", description = "Print the raw JSON snapshot.")
    private boolean json;

    @Option(names = "--client", paramLabel = "NAME", defaultValue = "${env:HABLA_CLIENT}",
            description = "The client name to authenticate as, where the endpoint requires it (or HABLA_CLIENT).")
    private String client;

    @Option(names = "--tls-trust", paramLabel = "PEM",
            description = "The endpoint speaks TLS: trust this certificate (the lab's, see docs/security.md).")
    private java.nio.file.Path tlsTrust;

    @Option(names = "--token-file", paramLabel = "FILE",
            description = "A file whose first line is the client's token (else the HABLA_TOKEN environment variable).")
    private java.nio.file.Path tokenFile;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        JsonNode status;
        try (Socket plain = new Socket()) {
            plain.connect(new InetSocketAddress(host, port), 2_000);
            plain.setSoTimeout(5_000);
            Socket s = tlsTrust == null ? plain
                    : org.habla.security.Tls.client(tlsTrust).connect(plain, host, port, 5_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
            String line = in.readLine();
            JsonNode first = line == null ? null : new ObjectMapper().readTree(line);
            if (first != null && first.path("type").asText().equals("hello")
                    && first.path("auth").asText().equals("required")) {
                String token = token();
                if (client == null || client.isBlank() || token == null) {
                    err.println("habla status: the status endpoint at " + host + ":" + port + " requires "
                            + "authentication: give --client NAME and --token-file FILE (or HABLA_CLIENT, HABLA_TOKEN)");
                    return ExitCodes.RUNTIME_FAILURE;
                }
                s.getOutputStream().write((new ObjectMapper().createObjectNode().put("op", "auth")
                        .put("client", client).put("token", token).toString() + "\n").getBytes(StandardCharsets.UTF_8));
                s.getOutputStream().flush();
                line = in.readLine();
                JsonNode answer = line == null ? null : new ObjectMapper().readTree(line);
                if (answer != null && answer.path("type").asText().equals("error")) {
                    err.println("habla status: refused: " + answer.path("code").asText() + ": "
                            + answer.path("message").asText());
                    return ExitCodes.RUNTIME_FAILURE;
                }
            }
            if (line == null) {
                err.println("habla status: the daemon at " + host + ":" + port + " closed without a status line");
                return ExitCodes.RUNTIME_FAILURE;
            }
            status = new ObjectMapper().readTree(line);
        } catch (IOException e) {
            err.println("habla status: no daemon status at " + host + ":" + port + " (" + e.getMessage() + ")");
            return ExitCodes.RUNTIME_FAILURE;
        }
        if (json) {
            out.println(status.toPrettyString());
        } else {
            print(status, out);
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** The token from --token-file, or HABLA_TOKEN; null when neither is given. */
    private String token() throws IOException {
        if (tokenFile != null) {
            return java.nio.file.Files.readString(tokenFile).lines().findFirst().orElse("").strip();
        }
        String env = System.getenv("HABLA_TOKEN");
        return env == null || env.isBlank() ? null : env.strip();
    }

    static void print(JsonNode st, PrintWriter out) {
        JsonNode w = st.path("watchdog");
        out.printf(Locale.ROOT, "system %s, up %.0f s, watchdog %s (%d trips, timeout %d ms)%n",
                st.path("system").asText(), st.path("uptimeS").asDouble(),
                w.path("tripped").asBoolean() ? "TRIPPED" : "ok", w.path("trips").asLong(), w.path("timeoutMs").asLong());
        out.println();
        out.printf(Locale.ROOT, "%-14s %-10s %-6s %9s %9s %9s%n", "INTERFACE", "DRIVER", "LINK", "MALFORMED", "SENT",
                "DROPPED");
        for (JsonNode i : st.path("interfaces")) {
            out.printf(Locale.ROOT, "%-14s %-10s %-6s %9d %9d %9d%n", i.path("id").asText(), i.path("driver").asText(),
                    i.path("up").asBoolean() ? "up" : "DOWN", i.path("malformed").asLong(),
                    i.path("commandsSent").asLong(), i.path("commandsDropped").asLong());
        }
        out.println();
        out.printf(Locale.ROOT, "%-22s %-17s %-8s %-5s %10s %8s %9s %9s %8s%n", "METHOD", "LAYER", "STATE", "STALE",
                "HANDLED", "PER S", "P50 US", "P99 US", "DROPS");
        for (JsonNode m : st.path("methods")) {
            long drops = 0;
            for (JsonNode in : m.path("inputs")) {
                drops += in.path("dropped").asLong();
            }
            String state = m.path("state").asText() + (m.path("ready").asBoolean(true) ? "" : "*");
            out.printf(Locale.ROOT, "%-22s %-17s %-8s %-5s %10d %8.1f %9s %9s %8d%n", m.path("id").asText(),
                    m.path("layer").asText(), state, m.path("stale").asBoolean() ? "yes" : "no",
                    m.path("handled").asLong(), m.path("handledPerS").asDouble(),
                    m.path("latency").path("p50Us").asText("-"), m.path("latency").path("p99Us").asText("-"), drops);
        }
        boolean placed = false;
        for (JsonNode m : st.path("methods")) {
            JsonNode p = m.path("placement");
            if (p.isMissingNode()) {
                continue;
            }
            if (!placed) {
                placed = true;
                out.println();
                out.printf(Locale.ROOT, "%-22s %-22s %-5s %-8s %9s %9s %8s  %s%n", "PLACED METHOD", "WORKER", "LINK",
                        "FALLBACK", "SENT", "RECEIVED", "DROPS", "LAST ERROR");
            }
            out.printf(Locale.ROOT, "%-22s %-22s %-5s %-8s %9d %9d %8d  %s%n", m.path("id").asText(),
                    p.path("host").asText(), p.path("up").asBoolean() ? "up" : "LOST", p.path("fallback").asText(),
                    p.path("sent").asLong(), p.path("received").asLong(), p.path("dropped").asLong(),
                    p.path("lastError").asText(""));
        }
        if (st.has("sockets")) {
            out.println();
            out.printf(Locale.ROOT, "%-18s %6s %8s %10s %8s %8s %8s  %s%n", "SOCKET", "PORT", "CLIENTS", "LINES OUT",
                    "DROPS", "EVICTED", "TIMEOUTS", "COMMANDED BY");
            for (JsonNode s : st.path("sockets")) {
                out.printf(Locale.ROOT, "%-18s %6d %8d %10d %8d %8d %8d  %s%n", s.path("socket").asText(),
                        s.path("port").asInt(), s.path("clients").asInt(), s.path("linesOut").asLong(),
                        s.path("dropped").asLong(), s.path("evicted").asLong(),
                        s.path("idleTimeouts").asLong() + s.path("frameTimeouts").asLong(), commander(s.path("control")));
            }
            long failures = 0;
            java.util.List<String> guarded = new java.util.ArrayList<>();
            for (JsonNode s : st.path("sockets")) {
                if (s.path("auth").asText().equals("required")) {
                    guarded.add(s.path("socket").asText() + (s.path("tls").asBoolean() ? " (TLS)" : ""));
                    failures += s.path("authFailures").asLong();
                }
            }
            JsonNode endpoint = st.path("statusEndpoint");
            if (endpoint.path("auth").asText().equals("required")) {
                guarded.add("the status endpoint");
                failures += endpoint.path("authFailures").asLong();
            }
            if (!guarded.isEmpty()) {
                out.printf(Locale.ROOT, "authentication required on %s; %d failed attempts%n",
                        String.join(", ", guarded), failures);
            }
            if (st.has("blocks")) {
                out.printf(Locale.ROOT, "blocks in flight: %d of %d bytes%n", st.path("blocks").path("bytesInFlight")
                        .asLong(), st.path("blocks").path("budgetBytes").asLong());
            }
        }
        out.println("(* = not ready yet)");
    }

    /** Who commands an actuating socket, for the table: "-" where values move nothing, "nobody" when free. */
    static String commander(JsonNode control) {
        if (control.isMissingNode()) {
            return "-";
        }
        JsonNode h = control.path("holder");
        if (h.isNull() || h.isMissingNode()) {
            return "nobody";
        }
        String client = h.path("client").asText("anonymous");
        return String.format(Locale.ROOT, "%s%s %s since %s (silent %d ms)",
                client.equals("anonymous") ? "" : client + " ", h.path("connection").asText(),
                h.path("address").asText(), control.path("since").asText(), control.path("silentMs").asLong());
    }
}
