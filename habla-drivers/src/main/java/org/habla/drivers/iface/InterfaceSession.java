package org.habla.drivers.iface;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.habla.net.Limits;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.SampleCodec;
import org.habla.sample.Payload;

/**
 * One connection to an interface program, speaking {@code habla-interface/1} with the shared HABLA framing.
 *
 * <pre>
 *   interface program                                   HABLA
 *   {"type":"hello","protocol":"habla-interface/1",
 *    "robot":NAME,"channels":[...]}              --&gt;    checked against the config (handshake)
 *   {"type":"reading","channel":C,"t":MICROS,
 *    "value":...}  (binary kinds: "bytes":N + N bytes) --&gt; sink.reading(C, value[, t])
 *                                                &lt;--    {"type":"command","channel":C,"value":...}
 *                                                &lt;--    {"type":"stop"}   every motion must stop
 *                                                &lt;--    {"type":"ping"}   every keepAliveMs; no answer needed
 *                                                &lt;--    {"type":"bye"}    HABLA is shutting down
 * </pre>
 *
 * A reading that cannot be used (an unknown channel, a value of the wrong kind, a line that is not a frame)
 * is reported as malformed and skipped; only a broken stream ends the connection.
 */
final class InterfaceSession implements LinkSession {

    static final String PROTOCOL = "habla-interface/1";

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private final Map<String, ChannelDescriptor> readings = new LinkedHashMap<>();
    private final Map<String, ChannelDescriptor> commands = new LinkedHashMap<>();
    private final List<ChannelDescriptor> expected;
    private final Duration keepAlive;
    private final Limits limits = Limits.DEFAULTS;
    private InputStream readerStream;
    private FrameReader reader;
    private OutputStream writerStream;
    private FrameWriter writer;

    InterfaceSession(List<ChannelDescriptor> expected, Duration keepAlive) {
        this.expected = List.copyOf(expected);
        this.keepAlive = keepAlive;
        for (ChannelDescriptor c : expected) {
            (c.direction() == ChannelDescriptor.Direction.READING ? readings : commands).put(c.name(), c);
        }
    }

    @Override
    public void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
        Frame hello;
        try {
            hello = reader(in).read();
        } catch (FrameException e) {
            throw new IOException("the interface program's hello is not a frame: " + e.code() + ": " + e.getMessage());
        }
        if (hello == null) {
            throw new EOFException("the interface program closed the connection before its hello");
        }
        Hello announced = Hello.parse(hello.header(), PROTOCOL);
        announced.check(expected);
        ObjectNode info = NODES.objectNode().put("protocol", PROTOCOL).put("robot", announced.robot());
        info.set("channels", hello.header().path("channels").deepCopy());
        sink.robotInfo(info);
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        Frame frame;
        try {
            frame = reader(in).read();
        } catch (FrameException e) {
            if (e.fatal()) {
                throw new IOException("the interface stream broke: " + e.code() + ": " + e.getMessage(), e);
            }
            sink.malformed(e.code() + ": " + e.getMessage());
            return;
        }
        if (frame == null) {
            throw new EOFException("the interface program closed the connection");
        }
        switch (frame.type()) {
            case "reading" -> reading(frame, sink);
            case "pong" -> { }
            default -> sink.malformed("unexpected frame type '" + frame.type() + "' (expected \"reading\")");
        }
    }

    private static void reading(Frame frame, ReadingSink sink, Map<String, ChannelDescriptor> readings) {
        ObjectNode h = frame.header();
        String name = h.path("channel").asText("");
        ChannelDescriptor channel = readings.get(name);
        if (channel == null) {
            sink.malformed("a reading on unknown channel '" + name + "'");
            return;
        }
        Payload value;
        try {
            value = SampleCodec.value(frame, channel.kind());
        } catch (FrameException e) {
            sink.malformed("channel '" + name + "': " + e.getMessage());
            return;
        }
        JsonNode t = h.get("t");
        if (t == null) {
            sink.reading(name, value);
        } else if (t.isIntegralNumber() && t.canConvertToLong() && t.longValue() > 0) {
            sink.reading(name, value, t.longValue());
        } else {
            sink.malformed("channel '" + name + "': \"t\" must be microseconds since the epoch, was " + t);
        }
    }

    private void reading(Frame frame, ReadingSink sink) {
        reading(frame, sink, readings);
    }

    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        ChannelDescriptor c = commands.get(channel);
        if (c == null) {
            throw new IOException("the interface has no command channel '" + channel + "'");
        }
        if (!c.kind().accepts(command.kind())) {
            throw new IllegalArgumentException("command channel '" + channel + "' takes " + c.kind().wireName()
                    + ", not " + command.kind().wireName());
        }
        writer(out).send(SampleCodec.withValue(NODES.objectNode().put("type", "command").put("channel", channel),
                command));
    }

    @Override
    public Optional<Duration> keepAlivePeriod() {
        return Optional.of(keepAlive);
    }

    @Override
    public void keepAlive(OutputStream out) throws IOException {
        writer(out).send(NODES.objectNode().put("type", "ping"));
    }

    @Override
    public void stopMotion(OutputStream out) throws IOException {
        writer(out).send(NODES.objectNode().put("type", "stop"));
    }

    @Override
    public void goodbye(OutputStream out) throws IOException {
        writer(out).send(NODES.objectNode().put("type", "bye"));
    }

    /** The reader of this connection's stream; it buffers, so the same one serves the handshake and every read. */
    private FrameReader reader(InputStream in) {
        if (reader == null || readerStream != in) {
            reader = new FrameReader(in, limits.maxLineBytes(), limits.maxBinaryBytes());
            readerStream = in;
        }
        return reader;
    }

    private FrameWriter writer(OutputStream out) {
        if (writer == null || writerStream != out) {
            writer = new FrameWriter(out);
            writerStream = out;
        }
        return writer;
    }
}
