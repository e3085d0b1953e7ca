package org.habla.sim.monitor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The live monitor in a real browser (Debian's headless Chromium) against a daemon running config/pioneer.json
 * on the simulated Pioneer: the page shows the graph's 21 methods coloured by state, the distance plot moves,
 * the robot link turns red within a second of the simulator dying and green when it is back. Screenshots of each
 * state go to target/monitor-screenshots (docs/figures has copies).
 */
@Timeout(180)
class MonitorInBrowserTest {

    private static final Path SHOTS = Path.of("target/monitor-screenshots");
    private static final String LINK_STATE = "const r = document.getElementById('link-robot');"
            + "return r ? r.className : '';";

    @Test
    void thePageFollowsThePioneerAndItsLinkThroughASimulatorRestart(@TempDir Path profile) throws Exception {
        PioneerSim sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 1));
        PioneerSimOptions samePorts = new PioneerSimOptions(World.builtIn("pioneer-room"), 1, 42, sim.arcosPort(),
                sim.micPort(), sim.keysPort(), 0, false, PioneerSimOptions.DEFAULT_SONAR_NOISE_M);
        PluginRegistry registry = PluginRegistry.discover(getClass().getClassLoader());
        HablaConfig cfg = new ConfigLoader(registry).parse(pioneerConfig(sim));
        try (Daemon daemon = Daemon.start(cfg, registry, EngineClock.system());
             Browser browser = new Browser(profile)) {
            browser.open("http://127.0.0.1:" + daemon.extensionPort(Daemon.MONITOR) + "/");

            Browser.await("the graph shows 21 methods, each coloured by its state", 30_000, () -> browser.jsLong(
                    "return document.querySelectorAll('#graph g.node.running[id^=\"method:\"]').length") == 21);
            assertThat(browser.jsLong("return document.querySelectorAll('#graph g.node[id^=\"method:\"]').length"))
                    .isEqualTo(21);
            assertThat(browser.jsLong("return document.querySelectorAll('#methods tbody tr').length")).isEqualTo(21);
            Browser.await("the robot link is shown up", 15_000, () -> browser.js(LINK_STATE).equals("up"));
            browser.screenshot(SHOTS.resolve("monitor-running.png"));

            browser.js("document.getElementById('method:distance').dispatchEvent(new MouseEvent('click'))");
            String points = "const p = window.hablaMonitor.plots['distance.distance_angle'];"
                    + "return p ? p.data[0].length : 0;";
            String lastX = "const p = window.hablaMonitor.plots['distance.distance_angle'];"
                    + "return p && p.data[0].length ? p.data[0][p.data[0].length - 1] * 1000 : 0;";
            Browser.await("the distance plot has points", 15_000, () -> browser.jsLong(points) >= 3);
            long firstEnd = browser.jsLong(lastX);
            long firstCount = browser.jsLong(points);
            Browser.await("the distance plot moves on", 15_000,
                    () -> browser.jsLong(lastX) > firstEnd + 500 && browser.jsLong(points) > firstCount);
            assertThat(browser.jsTrue("return document.querySelector('#out-distance_distance_angle .last')"
                    + ".textContent.includes('distanceM')")).isTrue();
            browser.screenshot(SHOTS.resolve("monitor-distance.png"));

            sim.close();
            // How soon is printed below; the test waits for the state, as a busy machine may be slow to draw it.
            long redMs = Browser.await("the robot link turns red after the simulator's end", 30_000,
                    () -> browser.js(LINK_STATE).equals("down"));
            assertThat(browser.jsTrue("return document.querySelector('#graph g.node[id=\"@robot.sonar\"]')"
                    + ".classList.contains('link-down')")).isTrue();
            Browser.await("what depends on the robot is drawn stale", 30_000, () -> browser.jsTrue(
                    "return document.getElementById('method:distance').classList.contains('stale')"));
            browser.screenshot(SHOTS.resolve("monitor-link-down.png"));

            sim = PioneerSim.start(samePorts);
            Browser.await("the robot link turns green again", 60_000, () -> browser.js(LINK_STATE).equals("up"));
            Browser.await("the methods are fresh again", 15_000, () -> browser.jsLong(
                    "return document.querySelectorAll('#graph g.node.running[id^=\"method:\"]').length") == 21);
            browser.screenshot(SHOTS.resolve("monitor-link-back.png"));
            System.out.println("monitor: the robot link was drawn red " + redMs + " ms after the simulator closed");
        } finally {
            sim.close();
        }
    }

    /** config/pioneer.json pointed at the simulator, with free ports for its sockets and its monitor. */
    static String pioneerConfig(PioneerSim sim) throws Exception {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = (ObjectNode) json.readTree(Files.readString(Path.of("../config/pioneer.json")));
        for (var i : root.withArray("interfaces")) {
            int port = switch (i.path("id").asText()) {
                case "robot" -> sim.arcosPort();
                case "mic" -> sim.micPort();
                default -> sim.keysPort();
            };
            ((ObjectNode) i).put("address", "127.0.0.1:" + port);
        }
        for (var m : root.withArray("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", freePort());
            }
        }
        root.putObject("status").put("port", 0).put("monitorPort", freePort());
        return json.writeValueAsString(root);
    }

    /** Ports {@link #freePort} has handed out in this JVM. */
    private static final Set<Integer> GIVEN = ConcurrentHashMap.newKeySet();

    /**
     * A free port not handed out before in this JVM: the kernel may give the same free port to two binds in a row,
     * and a config asking for one twice is refused ("duplicate port").
     */
    static int freePort() throws Exception {
        for (int attempt = 0; attempt < 1000; attempt++) {
            try (ServerSocket s = new ServerSocket(0)) {
                if (GIVEN.add(s.getLocalPort())) {
                    return s.getLocalPort();
                }
            }
        }
        throw new java.io.IOException("no free port left that was not handed out before");
    }
}
