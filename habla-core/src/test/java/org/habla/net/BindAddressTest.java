package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.StandardProtocolFamily;
import java.nio.channels.ServerSocketChannel;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

class BindAddressTest {

    @Test
    void nothingGivenIsTheIpv4Loopback() throws Exception {
        assertThat(BindAddress.of(null).address()).isEqualTo(InetAddress.getByName("127.0.0.1"));
        assertThat(BindAddress.of(" ").toString()).isEqualTo("127.0.0.1");
    }

    @Test
    void eachAddressGetsASocketOfItsOwnFamily() throws Exception {
        assertThat(BindAddress.of("0.0.0.0").family()).isEqualTo(StandardProtocolFamily.INET);
        assertThat(BindAddress.of("::").family()).isEqualTo(StandardProtocolFamily.INET6);
    }

    @Test
    void theIpv4WildcardIsReachedOnIpv4LoopbackOnly() throws Exception {
        Assumptions.assumeTrue(org.habla.testing.DaemonProcess.ipv6Loopback(), "this computer has no IPv6 loopback");
        BindAddress any = BindAddress.of("0.0.0.0");
        try (ServerSocketChannel server = any.listen(0, 1)) {
            int port = server.socket().getLocalPort();
            assertThat(any.local()).isEqualTo(InetAddress.getByName("127.0.0.1"));
            assertThat(connects("127.0.0.1", port)).isTrue();
            assertThat(connects("::1", port)).isFalse();
        }
    }

    @Test
    void theIpv6WildcardIsReachedOnBothLoopbacks() throws Exception {
        Assumptions.assumeTrue(org.habla.testing.DaemonProcess.ipv6Loopback(), "this computer has no IPv6 loopback");
        BindAddress any = BindAddress.of("::");
        try (ServerSocketChannel server = any.listen(0, 1)) {
            int port = server.socket().getLocalPort();
            assertThat(any.local()).isEqualTo(InetAddress.getByName("::1"));
            assertThat(connects("::1", port)).isTrue();
            assertThat(connects("127.0.0.1", port)).isTrue();
        }
    }

    @Test
    void aProbeFailsOnATakenPortAndLeavesAFreeOneFree() throws Exception {
        BindAddress loopback = BindAddress.of("127.0.0.1");
        try (ServerSocketChannel server = loopback.listen(0, 1)) {
            int port = server.socket().getLocalPort();
            assertThatThrownBy(() -> loopback.probe(port)).isInstanceOf(IOException.class);
        }
        int free;
        try (ServerSocketChannel server = loopback.listen(0, 1)) {
            free = server.socket().getLocalPort();
        }
        loopback.probe(free);
        try (ServerSocketChannel again = loopback.listen(free, 1)) {
            assertThat(again.socket().getLocalPort()).isEqualTo(free);
        }
    }

    private static boolean connects(String host, int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(InetAddress.getByName(host), port), 2_000);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
