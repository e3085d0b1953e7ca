package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class StatusCommandTest {

    @Test
    void theSocketTableNamesWhoCommandsEachActuatingSocket() throws Exception {
        JsonNode st = new ObjectMapper().readTree("""
                {"system": "s", "watchdog": {}, "sockets": [
                  {"socket": "action", "port": 7004, "clients": 2, "control": {"holder":
                    {"connection": "action#3", "address": "127.0.0.1:53422"}, "since": "2025-01-01T10:00:00Z",
                    "silentMs": 120}},
                  {"socket": "say", "port": 7013, "clients": 0, "control": {"holder": null}},
                  {"socket": "distance_angle", "port": 7002, "clients": 1}]}
                """);
        StringWriter text = new StringWriter();
        StatusCommand.print(st, new PrintWriter(text));
        String[] lines = text.toString().split("\n");
        assertThat(text.toString()).contains("COMMANDED BY");
        assertThat(line(lines, "action")).endsWith("action#3 127.0.0.1:53422 since 2025-01-01T10:00:00Z (silent 120 ms)");
        assertThat(line(lines, "say")).endsWith("nobody");
        assertThat(line(lines, "distance_angle")).endsWith("-");
    }

    private static String line(String[] lines, String socket) {
        for (String l : lines) {
            if (l.startsWith(socket + " ")) {
                return l.stripTrailing();
            }
        }
        throw new AssertionError("no line for socket " + socket);
    }
}
