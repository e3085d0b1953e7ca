package org.habla.daemon;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import org.habla.config.ConfigLoader;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A daemon listens on exactly the address its config names: {@code 0.0.0.0} is every IPv4 address and no IPv6
 * one, {@code ::} is both (the kernel's dual stack). Checked on the loopback addresses of both families.
 */
@Timeout(60)
public class DaemonBindAddressTest {

    private static final int CONNECT_MILLIS = 2_000;

    private static Daemon daemon(String bind, int[] ports) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        String json = """
                {"system": "bind", "safety": {"watchdogMs": 0}, "security": {"insecure": true},
                 "status": {"bind": "%1$s", "port": %2$d, "monitorPort": %3$d, "monitorBind": "%1$s"},
                 "methods": [{"id": "cmd", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                              "params": {"kind": "number"}, "expose": {"port": %4$d, "bind": "%1$s"}}]}
                """.formatted(bind, ports[0], ports[1], ports[2]);
        return Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
    }

    @Test
    void allIpv4AddressesIsNotIpv6() throws Exception {
        Assumptions.assumeTrue(DaemonProcess.ipv6Loopback(), "this computer has no IPv6 loopback");
        int[] ports = DaemonProcess.freePorts(3);
        try (Daemon d = daemon("0.0.0.0", ports)) {
            for (int port : new int[] {d.statusPort(), d.extensionPort(Daemon.MONITOR), d.port("cmd")}) {
                assertThat(connects("127.0.0.1", port)).as("127.0.0.1:%d", port).isTrue();
                assertThat(connects("::1", port)).as("[::1]:%d", port).isFalse();
            }
        }
        for (int port : ports) {
            try (var again = org.habla.net.BindAddress.of("0.0.0.0").listen(port, 1)) {
                assertThat(again.isOpen()).as("port %d is free again once the daemon is closed", port).isTrue();
            }
        }
    }

    @Test
    void theIpv6WildcardListensOnBothFamilies() throws Exception {
        Assumptions.assumeTrue(DaemonProcess.ipv6Loopback(), "this computer has no IPv6 loopback");
        int[] ports = DaemonProcess.freePorts(3);
        try (Daemon d = daemon("::", ports)) {
            for (int port : new int[] {d.statusPort(), d.extensionPort(Daemon.MONITOR), d.port("cmd")}) {
                assertThat(connects("::1", port)).as("[::1]:%d", port).isTrue();
                assertThat(connects("127.0.0.1", port)).as("127.0.0.1:%d", port).isTrue();
            }
        }
    }

    private static boolean connects(String host, int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(InetAddress.getByName(host), port), CONNECT_MILLIS);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
