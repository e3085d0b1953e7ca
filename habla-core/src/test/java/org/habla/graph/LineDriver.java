package org.habla.graph;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.LinkSession;
import org.habla.driver.Liveness;
import org.habla.driver.ReadingSink;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.NoParams;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * A tiny text protocol for engine tests: the robot sends {@code "<channel> <number>\n"}, HABLA sends
 * {@code "cmd <channel> <number>\n"}, {@code "stop\n"} and {@code "ping\n"}; the handshake is
 * {@code "hello\n"} → {@code "ready\n"}. The robot tells of a device behind a channel with
 * {@code "device <name> online|offline <channel>\n"}: a reading channel of an offline device is unavailable, and a
 * command to a command channel of one is refused.
 */
final class LineDriver implements Driver {

    private final int port;
    /** Whether a second connection ({@code aux}, on the next port) brings readings too. */
    private final boolean pair;

    LineDriver(int port) {
        this(port, false);
    }

    LineDriver(int port, boolean pair) {
        this.port = port;
        this.pair = pair;
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return List.of(ChannelDescriptor.reading("value", PayloadKind.NUMBER, "m"),
                ChannelDescriptor.command("motor", PayloadKind.NUMBER, "m/s", true));
    }

    @Override
    public List<Connection> connections() {
        Connection main = new Connection("main", port, Set.of("motor"), Liveness.quiet(), Session::new);
        return pair ? List.of(main, new Connection("aux", port + 1, Set.of(), Liveness.quiet(), Session::new))
                : List.of(main);
    }

    static String readLine(InputStream in) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        for (int c = in.read(); c != '\n'; c = in.read()) {
            if (c < 0) {
                throw new java.io.EOFException("robot closed the connection");
            }
            b.write(c);
        }
        return b.toString(StandardCharsets.UTF_8);
    }

    static final class Session implements LinkSession {

        /** The offline device behind each command channel. */
        private final java.util.Map<String, String> offline = new java.util.concurrent.ConcurrentHashMap<>();

        @Override
        public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
            out.write("hello\n".getBytes(StandardCharsets.UTF_8));
            out.flush();
            String reply = readLine(in);
            if (!reply.equals("ready")) {
                throw new IOException("expected ready, got " + reply);
            }
        }

        @Override
        public void readNext(InputStream in, ReadingSink sink) throws IOException {
            String[] parts = readLine(in).split(" ");
            if (parts[0].equals("device") && parts.length == 4) {
                boolean online = parts[2].equals("online");
                sink.device(parts[1], online, "the robot says " + parts[2]);
                if (parts[3].equals("motor")) {
                    if (online) {
                        offline.remove(parts[3]);
                    } else {
                        offline.put(parts[3], parts[1]);
                    }
                } else {
                    sink.availability(parts[3], online, parts[1] + " is " + parts[2]);
                }
                return;
            }
            try {
                sink.reading(parts[0], new NumberValue(Double.parseDouble(parts[1])));
            } catch (RuntimeException e) {
                sink.malformed("bad line: " + String.join(" ", parts));
            }
        }

        @Override
        public void write(String channel, Payload command, OutputStream out) throws IOException {
            String device = offline.get(channel);
            if (device != null) {
                throw new IllegalArgumentException("device " + device + " is offline");
            }
            out.write(("cmd " + channel + " " + ((NumberValue) command).value() + "\n").getBytes(StandardCharsets.UTF_8));
        }

        @Override
        public Optional<Duration> keepAlivePeriod() {
            return Optional.of(Duration.ofMillis(200));
        }

        @Override
        public void keepAlive(OutputStream out) throws IOException {
            out.write("ping\n".getBytes(StandardCharsets.UTF_8));
        }

        @Override
        public void stopMotion(OutputStream out) throws IOException {
            out.write("stop\n".getBytes(StandardCharsets.UTF_8));
        }
    }

    static final class Provider implements DriverProvider<NoParams> {
        @Override
        public String name() {
            return "lines-test";
        }

        @Override
        public String description() {
            return "test line protocol";
        }

        @Override
        public Class<NoParams> paramsType() {
            return NoParams.class;
        }

        @Override
        public Driver create(InterfaceAddress address, NoParams params) {
            return new LineDriver(address.portOr(1));
        }
    }

    /** The same protocol over two connections, {@code main} and {@code aux} (for tests of what two readers change). */
    static final class PairProvider implements DriverProvider<NoParams> {
        @Override
        public String name() {
            return "lines-test-pair";
        }

        @Override
        public String description() {
            return "test line protocol over two connections";
        }

        @Override
        public Class<NoParams> paramsType() {
            return NoParams.class;
        }

        @Override
        public Driver create(InterfaceAddress address, NoParams params) {
            return new LineDriver(address.portOr(1), true);
        }
    }
}
