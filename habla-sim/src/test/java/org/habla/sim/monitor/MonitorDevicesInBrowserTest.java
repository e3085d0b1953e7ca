package org.habla.sim.monitor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The live monitor in a real browser against a daemon running config/room.json on a real Mosquitto broker: a
 * Zigbee sensor that goes offline gets a red row under its interface, the channels it feeds are drawn down while
 * the broker link stays up, and the methods it made stale say so; all of it goes back when the sensor is online.
 */
@Timeout(120)
class MonitorDevicesInBrowserTest {

    private static final String AVAILABILITY = "zigbee2mqtt/desk_motion/availability";
    private static final String DEVICE_ROW = "const r = document.getElementById('device-room-desk_motion');"
            + "return r ? r.className + ' | ' + r.textContent : '';";
    private static final String NODE = "const g = document.querySelector('#graph g.node[id=\"' + arguments[0] + '\"]');"
            + "return g ? g.getAttribute('class') : '';";
    private static final String STATE_CELL = "const r = document.getElementById('row-desk-motion');"
            + "return r ? r.children[3].textContent + ' | ' + (r.children[3].title || '') : '';";

    /** config/room.json on the test's broker, its status endpoint off and its monitor on a free port. */
    private static String roomConfig(int brokerPort) throws Exception {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = (ObjectNode) json.readTree(Path.of("../config/room.json").toFile());
        root.remove("$schema");
        ((ObjectNode) root.get("interfaces").get(0)).put("address", "127.0.0.1:" + brokerPort);
        root.putObject("status").put("port", 0).put("monitorPort", MonitorInBrowserTest.freePort());
        for (JsonNode m : root.get("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", MonitorInBrowserTest.freePort());
            }
        }
        return root.toString();
    }

    @Test
    void anOfflineSensorIsShownUnderItsLinkWithTheChannelsAndMethodsItMadeStale(@TempDir Path tmp) throws Exception {
        PluginRegistry registry = PluginRegistry.discover(getClass().getClassLoader());
        try (Mosquitto broker = Mosquitto.start(tmp);
                Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(roomConfig(broker.port())), registry,
                        EngineClock.system());
                Browser browser = new Browser(tmp.resolve("profile"))) {
            broker.publish(AVAILABILITY, "online", true);
            browser.open("http://127.0.0.1:" + daemon.extensionPort(Daemon.MONITOR) + "/");
            Browser.await("the sensor is listed online", 30_000, () -> browser.js(DEVICE_ROW).toString()
                    .startsWith("device up"));

            broker.publish(AVAILABILITY, "offline", true);
            Browser.await("the sensor's row turns red", 15_000, () -> browser.js(DEVICE_ROW).toString()
                    .startsWith("device down"));
            assertThat(browser.js(DEVICE_ROW).toString()).contains("desk_motion", "OFFLINE",
                    AVAILABILITY + " says offline");
            assertThat(browser.js("return document.getElementById('link-room').className")).isEqualTo("up");
            Browser.await("its channels are drawn down", 15_000, () -> browser.js(NODE, "@room.desk_motion")
                    .toString().contains("link-down") && browser.js(NODE, "@room.desk_lux").toString()
                    .contains("link-down"));
            assertThat(browser.js(NODE, "@room.sofa_motion").toString()).contains("link-up");
            assertThat(browser.js(STATE_CELL).toString()).startsWith("running, stale (@room.desk_motion) | ")
                    .contains("desk_motion is offline");
            browser.screenshot(Path.of("target/monitor-screenshots/monitor-device-offline.png"));

            broker.publish(AVAILABILITY, "online", true);
            Browser.await("the sensor's row is green again", 15_000, () -> browser.js(DEVICE_ROW).toString()
                    .startsWith("device up"));
            Browser.await("its channels are drawn up", 15_000, () -> browser.js(NODE, "@room.desk_motion")
                    .toString().contains("link-up"));
            Browser.await("the method is fresh", 15_000, () -> browser.js(STATE_CELL).toString()
                    .startsWith("running | "));
        }
    }
}
