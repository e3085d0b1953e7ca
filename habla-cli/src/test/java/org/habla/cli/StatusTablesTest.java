package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class StatusTablesTest {

    @Test
    void theSocketTableNamesWhoCommandsEachActuatingSocket() throws Exception {
        JsonNode st = new ObjectMapper().readTree("""
                {"system": "s", "watchdog": {}, "sockets": [
                  {"socket": "action", "port": 7004, "clients": 2, "control": {"holder":
                    {"connection": "action#3", "address": "127.0.0.1:53422"}, "since": "2025-01-01T10:00:00Z",
                    "silentMs": 120}},
                  {"socket": "say", "port": 7013, "clients": 0, "control": {"holder": null}},
                  {"socket": "drive", "port": 7014, "clients": 1, "auth": "required", "authFailures": 2, "control":
                    {"holder": {"client": "mdb", "connection": "drive#1", "address": "10.0.0.9:5000"},
                    "since": "2025-01-01T10:00:00Z", "silentMs": 5}},
                  {"socket": "distance_angle", "port": 7002, "clients": 1}],
                 "statusEndpoint": {"auth": "required", "authenticated": 4, "authFailures": 3}}
                """);
        StringWriter text = new StringWriter();
        StatusTables.print(st, new PrintWriter(text));
        String[] lines = text.toString().split("\n");
        assertThat(text.toString()).contains("COMMANDED BY");
        assertThat(line(lines, "action")).endsWith("action#3 127.0.0.1:53422 since 2025-01-01T10:00:00Z (silent 120 ms)");
        assertThat(line(lines, "say")).endsWith("nobody");
        assertThat(line(lines, "drive")).endsWith("mdb drive#1 10.0.0.9:5000 since 2025-01-01T10:00:00Z (silent 5 ms)");
        assertThat(text.toString()).contains("authentication required on drive, the status endpoint; 5 failed attempts");
        assertThat(line(lines, "distance_angle")).endsWith("-");
    }

    @Test
    void everyBridgeHasARowWithItsBrokerLinkAndCounts() throws Exception {
        String text = tables("""
                {"system": "room", "watchdog": {}, "bridges": [
                  {"id": "home", "type": "mqtt", "broker": "127.0.0.1:1883", "connected": true, "connects": 2,
                   "published": 120, "dropped": 3, "actions": 4, "refused": 1},
                  {"id": "away", "type": "mqtt", "broker": "10.0.0.9:8883", "connected": false, "connects": 0,
                   "published": 0, "dropped": 7, "actions": 0, "refused": 0}]}
                """);
        assertThat(text).contains("BRIDGE");
        assertThat(line(text, "home")).matches("home +mqtt +127\\.0\\.0\\.1:1883 +up +2 +120 +3 +4 +1");
        assertThat(line(text, "away")).matches("away +mqtt +10\\.0\\.0\\.9:8883 +DOWN +0 +0 +7 +0 +0");
    }

    @Test
    void eachDeviceIsListedWithItsInterfaceStateAndWhatSaidSo() throws Exception {
        String text = tables("""
                {"system": "room", "watchdog": {}, "interfaces": [
                  {"id": "room", "driver": "mqtt", "up": true, "commandsSent": 3, "commandsDropped": 1,
                   "connections": [{"name": "broker", "up": true}],
                   "lastDrop": {"channel": "lamp", "why": "device hall_lamp is offline: z2m/hall_lamp/availability says offline"},
                   "devices": {
                     "hall_lamp": {"online": false, "detail": "z2m/hall_lamp/availability says offline"},
                     "hall_motion": {"online": true, "detail": "z2m/hall_motion/availability says online"}}}]}
                """);
        assertThat(text).contains("DEVICE");
        assertThat(line(text, "hall_lamp")).matches("hall_lamp +room +OFFLINE +z2m/hall_lamp/availability says offline");
        assertThat(line(text, "hall_motion")).matches("hall_motion +room +online +z2m/hall_motion/availability says online");
        assertThat(text).contains("room: the last command dropped, on lamp: device hall_lamp is offline: "
                + "z2m/hall_lamp/availability says offline");
    }

    @Test
    void aLinkDownSaysWhichConnectionAndWhy() throws Exception {
        String text = tables("""
                {"system": "room", "watchdog": {}, "interfaces": [
                  {"id": "room", "driver": "mqtt", "up": false, "connections": [
                    {"name": "broker", "up": false, "lastError": "Connection refused"}]}]}
                """);
        assertThat(line(text, "room")).contains("DOWN");
        assertThat(text).contains("room: connection broker is down: Connection refused");
    }

    @Test
    void everyStaleMethodSaysWhatMadeItStale() throws Exception {
        String text = tables("""
                {"system": "room", "watchdog": {}, "methods": [
                  {"id": "motion-raw", "layer": "sensors_actuators", "state": "RUNNING", "stale": true,
                   "staleBecause": {"source": "@room.motion", "why": "the device of @room.motion is unavailable: hall_motion is offline (z2m/hall_motion/availability)"}},
                  {"id": "lux", "layer": "sensors_actuators", "state": "RUNNING", "stale": false}]}
                """);
        assertThat(text).contains("STALE METHOD");
        assertThat(text.lines().filter(l -> l.startsWith("motion-raw ")).toList()).hasSize(2)
                .last().asString().matches("motion-raw +@room\\.motion +the device of @room\\.motion is unavailable: "
                        + "hall_motion is offline \\(z2m/hall_motion/availability\\)");
        assertThat(text.lines().filter(l -> l.startsWith("lux ")).toList()).hasSize(1);
    }

    private static String tables(String json) throws Exception {
        StringWriter text = new StringWriter();
        StatusTables.print(new ObjectMapper().readTree(json), new PrintWriter(text));
        return text.toString();
    }

    private static String line(String text, String first) {
        return line(text.split("\n"), first);
    }

    private static String line(String[] lines, String socket) {
        for (String l : lines) {
            if (l.startsWith(socket + " ")) {
                return l.stripTrailing();
            }
        }
        throw new AssertionError("no line for " + socket);
    }
}
