package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ChannelConnectionTest {

    private ServerSocketChannel server;
    private Socket peer;
    private ChannelConnection connection;

    @BeforeEach
    void connect() throws IOException {
        server = ServerSocketChannel.open().bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        peer = new Socket(InetAddress.getLoopbackAddress(), server.socket().getLocalPort());
        SocketChannel accepted = server.accept();
        connection = new ChannelConnection(accepted, ChannelReadiness.shared());
    }

    @AfterEach
    void close() throws IOException {
        connection.close();
        peer.close();
        server.close();
    }

    @Test
    void aReadWaitsForTheBytesThePeerSendsLater() throws Exception {
        AtomicReference<String> read = new AtomicReference<>();
        Thread reader = Thread.ofVirtual().start(() -> {
            try {
                byte[] b = new byte[5];
                int n = connection.in().readNBytes(b, 0, 5);
                read.set(new String(b, 0, n, UTF_8));
            } catch (IOException e) {
                read.set(e.toString());
            }
        });
        peer.getOutputStream().write("hel".getBytes(UTF_8));
        peer.getOutputStream().write("lo".getBytes(UTF_8));
        assertThat(reader.join(Duration.ofSeconds(10))).isTrue();
        assertThat(read.get()).isEqualTo("hello");
    }

    @Test
    void aReadEndsAtThePeersEndAndAtTheReadTimeout() throws Exception {
        connection.readTimeout(50);
        InputStream in = connection.in();
        assertThatThrownBy(() -> in.read(new byte[4])).isInstanceOf(SocketTimeoutException.class);
        peer.shutdownOutput();
        assertThat(in.read(new byte[4])).isEqualTo(-1);
    }

    @Test
    void closingWakesAReaderThatWaits() throws Exception {
        AtomicReference<Object> outcome = new AtomicReference<>();
        Thread reader = Thread.ofVirtual().start(() -> {
            try {
                outcome.set(connection.in().read(new byte[4]));
            } catch (IOException e) {
                outcome.set(e);
            }
        });
        while (reader.getState() != Thread.State.WAITING && reader.getState() != Thread.State.TIMED_WAITING
                && reader.isAlive()) {
            Thread.sleep(1); // until the reader parks for readiness
        }
        connection.close();
        assertThat(reader.join(Duration.ofSeconds(10))).isTrue();
        assertThat(outcome.get()).isInstanceOf(IOException.class);
    }

    @Test
    void aWriteThatCannotWaitTakesWhatTheSocketHasRoomForAndAWriteThatWaitsSendsTheRestOnceThePeerReads()
            throws Exception {
        byte[] block = new byte[64 * 1024];
        long taken = 0;
        int n;
        for (int i = 0; i < 10_000 && (n = connection.tryWrite(block)) > 0; i++) {
            taken += n; // the peer reads nothing: the buffers fill
        }
        assertThat(connection.tryWrite(block)).as("a full socket takes nothing and does not wait").isZero();
        long toSend = taken + block.length;
        Thread writer = Thread.ofVirtual().start(() -> {
            try {
                connection.out().write(block);
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
        InputStream in = peer.getInputStream();
        byte[] sink = new byte[64 * 1024];
        long received = 0;
        while (received < toSend) {
            int r = in.read(sink);
            assertThat(r).isPositive();
            received += r;
        }
        assertThat(writer.join(Duration.ofSeconds(10))).isTrue();
        assertThat(received).isEqualTo(toSend);
    }
}
