package org.habla.cli;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.util.Locale;

/** The tables {@code habla status} prints from a daemon's status snapshot. */
final class StatusTables {

    private StatusTables() {
    }

    /**
     * Prints every table: the interfaces (with why a link is down and the last command dropped), the devices the
     * drivers report, the methods, why each stale method is stale, placed methods, sockets and bridges.
     */
    static void print(JsonNode st, PrintWriter out) {
        JsonNode w = st.path("watchdog");
        out.printf(Locale.ROOT, "system %s, up %.0f s, watchdog %s (%d trips, timeout %d ms)%n",
                st.path("system").asText(), st.path("uptimeS").asDouble(),
                w.path("tripped").asBoolean() ? "TRIPPED" : "ok", w.path("trips").asLong(), w.path("timeoutMs").asLong());
        interfaces(st, out);
        devices(st, out);
        methods(st, out);
        stale(st, out);
        placements(st, out);
        sockets(st, out);
        bridges(st, out);
        out.println("(* = not ready yet)");
    }

    private static void interfaces(JsonNode st, PrintWriter out) {
        out.println();
        out.printf(Locale.ROOT, "%-14s %-10s %-6s %9s %9s %9s%n", "INTERFACE", "DRIVER", "LINK", "MALFORMED", "SENT",
                "DROPPED");
        for (JsonNode i : st.path("interfaces")) {
            out.printf(Locale.ROOT, "%-14s %-10s %-6s %9d %9d %9d%n", i.path("id").asText(), i.path("driver").asText(),
                    i.path("up").asBoolean() ? "up" : "DOWN", i.path("malformed").asLong(),
                    i.path("commandsSent").asLong(), i.path("commandsDropped").asLong());
        }
        for (JsonNode i : st.path("interfaces")) {
            for (JsonNode c : i.path("connections")) {
                if (!c.path("up").asBoolean(true)) {
                    out.printf(Locale.ROOT, "%s: connection %s%s is down%s%n", i.path("id").asText(),
                            c.path("name").asText(), c.path("optional").asBoolean() ? " (optional)" : "",
                            c.path("lastError").asText("").isEmpty() ? "" : ": " + c.path("lastError").asText());
                }
            }
            JsonNode drop = i.path("lastDrop");
            if (drop.isObject()) {
                out.printf(Locale.ROOT, "%s: the last command dropped, on %s: %s%n", i.path("id").asText(),
                        drop.path("channel").asText(), drop.path("why").asText());
            }
        }
    }

    /** Every device a driver reports, with its interface, so an offline one is named. */
    private static void devices(JsonNode st, PrintWriter out) {
        boolean any = false;
        for (JsonNode i : st.path("interfaces")) {
            var names = i.path("devices").fieldNames();
            while (names.hasNext()) {
                String name = names.next();
                JsonNode d = i.path("devices").path(name);
                if (!any) {
                    any = true;
                    out.println();
                    out.printf(Locale.ROOT, "%-22s %-14s %-8s %s%n", "DEVICE", "INTERFACE", "STATE", "DETAIL");
                }
                out.printf(Locale.ROOT, "%-22s %-14s %-8s %s%n", name, i.path("id").asText(),
                        d.path("online").asBoolean() ? "online" : "OFFLINE", d.path("detail").asText(""));
            }
        }
    }

    private static void methods(JsonNode st, PrintWriter out) {
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
    }

    /** Each stale method with what upstream made it stale: an interface, a channel's device, a worker. */
    private static void stale(JsonNode st, PrintWriter out) {
        boolean any = false;
        for (JsonNode m : st.path("methods")) {
            JsonNode because = m.path("staleBecause");
            if (!m.path("stale").asBoolean() || !because.isObject()) {
                continue;
            }
            if (!any) {
                any = true;
                out.println();
                out.printf(Locale.ROOT, "%-22s %-22s %s%n", "STALE METHOD", "BECAUSE OF", "WHY");
            }
            out.printf(Locale.ROOT, "%-22s %-22s %s%n", m.path("id").asText(), because.path("source").asText(),
                    because.path("why").asText());
        }
    }

    private static void placements(JsonNode st, PrintWriter out) {
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
    }

    private static void sockets(JsonNode st, PrintWriter out) {
        if (!st.has("sockets")) {
            return;
        }
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

    /** Every bridge: its broker, whether it is connected, and what it published, dropped, took and refused. */
    private static void bridges(JsonNode st, PrintWriter out) {
        if (!st.path("bridges").isArray() || st.path("bridges").isEmpty()) {
            return;
        }
        out.println();
        out.printf(Locale.ROOT, "%-14s %-6s %-22s %-5s %9s %10s %8s %8s %8s%n", "BRIDGE", "TYPE", "BROKER", "LINK",
                "CONNECTS", "PUBLISHED", "DROPPED", "ACTIONS", "REFUSED");
        for (JsonNode b : st.path("bridges")) {
            out.printf(Locale.ROOT, "%-14s %-6s %-22s %-5s %9d %10d %8d %8d %8d%n", b.path("id").asText(),
                    b.path("type").asText(), b.path("broker").asText(), b.path("connected").asBoolean() ? "up" : "DOWN",
                    b.path("connects").asLong(), b.path("published").asLong(), b.path("dropped").asLong(),
                    b.path("actions").asLong(), b.path("refused").asLong());
        }
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
