package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.List;
import java.util.OptionalInt;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.habla.config.InterfaceConfig;
import org.habla.config.Reconnect;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.Liveness;
import org.habla.plugin.NoParams;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An interface whose driver keeps a data connection and an optional one (a robot's menu server): with the
 * optional server absent the interface is up, and its link record says which connections are.
 */
@Timeout(30)
class OptionalConnectionTest {

    private static int closedPort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    @Test
    void anOptionalConnectionThatIsDownLeavesTheInterfaceUpAndTheLinkRecordNamesEachConnection() throws Exception {
        int menuPort = closedPort();
        try (FakeLineRobot robot = new FakeLineRobot(0)) {
            Driver driver = new Driver() {
                @Override
                public List<ChannelDescriptor> channels() {
                    return new LineDriver(robot.port()).channels();
                }

                @Override
                public List<Connection> connections() {
                    return List.of(new Connection("main", robot.port(), Set.of("motor"), Liveness.quiet(), LineDriver.Session::new),
                            new Connection("menu", menuPort, Set.of(), Liveness.quiet(), LineDriver.Session::new).asOptional());
                }
            };
            InterfaceConfig config = new InterfaceConfig("robot", "two-connections",
                    new InterfaceAddress("127.0.0.1", OptionalInt.of(robot.port())), new NoParams(),
                    new Reconnect(50, 200, 1_000, 5_000));
            EngineClock clock = EngineClock.system();
            InterfaceLink link = new InterfaceLink(config, new LiveDriver(driver), clock, new LinkStates());
            BlockingQueue<Sample> records = new LinkedBlockingQueue<>();
            link.reading("link").subscribe(records::add);
            link.start();
            try {
                RecordValue seen = null;
                long end = System.nanoTime() + 10_000_000_000L;
                while (System.nanoTime() < end) {
                    Sample s = records.poll(100, TimeUnit.MILLISECONDS);
                    if (s != null && ((RecordValue) s.payload()).get("up").booleanValue()) {
                        seen = (RecordValue) s.payload();
                        break;
                    }
                }

                assertThat(seen).as("a link record with up: true").isNotNull();
                assertThat(link.up()).isTrue();
                assertThat(seen.get("connections").get("main").booleanValue()).isTrue();
                assertThat(seen.get("connections").get("menu").booleanValue()).isFalse();
                assertThat(seen.text("detail")).startsWith("menu (optional) down");
            } finally {
                link.stop();
                clock.close();
            }
        }
    }
}
