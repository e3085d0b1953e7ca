package org.habla.drivers.mqtt;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.driver.ClientSession;
import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connection of an {@code mqtt} interface to its broker: subscribes to every reading's topic filter and every
 * device's availability topic, decodes what arrives on the link's reader thread, and publishes commands (never
 * retained).
 *
 * <pre>
 *   broker ──PUBLISH──▶ client library thread ──offer──▶ bounded queue ──readNext──▶ decoders ──▶ sink
 *   engine ──write(channel, value)──▶ template ──PUBLISH (retain = false)──▶ broker
 * </pre>
 *
 * A device whose availability topic says offline makes its reading channels unavailable (stale) and its commands
 * refused; the broker lost ends the session, and the engine's link reconnects with its back-off.
 */
final class MqttSession implements ClientSession {

    /** The reading channel of each of the driver's decoders, in their order. */
    private final List<SessionChannel> channels;

    private static final Logger LOG = LoggerFactory.getLogger(MqttSession.class);
    /** How often a reader waiting for a message looks whether the connection was lost. */
    private static final long POLL_MILLIS = 100;
    private static final com.fasterxml.jackson.databind.ObjectMapper JSON = new com.fasterxml.jackson.databind.ObjectMapper();

    private final MqttDriver driver;
    private final BlockingQueue<Message> queue;
    private final AtomicLong overflow = new AtomicLong();
    private final DeviceAvailability devices;
    private volatile MqttWire wire;
    private volatile Throwable lost;
    private volatile boolean closed;

    private record Message(String topic, byte[] payload) {
    }

    MqttSession(MqttDriver driver) {
        this.driver = driver;
        this.queue = new ArrayBlockingQueue<>(driver.params().queueMessages());
        this.devices = new DeviceAvailability(driver.devices());
        this.channels = driver.decoders().stream().map(d -> new SessionChannel(d.map().channel())).toList();
    }

    @Override
    public void open(ReadingSink sink, Duration timeout) throws IOException {
        MqttParams p = driver.params();
        BrokerEndpoint endpoint = new BrokerEndpoint(driver.host(), driver.port(), p.mqttVersion(), driver.clientId(),
                p.username(), BrokerLogin.password(p.password(), p.passwordFile()), BrokerLogin.tls(p.tls(), p.caFile()),
                p.keepAliveS(), Optional.empty());
        MqttWire w = MqttWire.to(endpoint, cause -> lost = cause == null ? new IOException("connection lost") : cause);
        wire = w;
        if (closed) {
            w.disconnect();
            throw new IOException("closed");
        }
        w.connect(timeout);
        Set<String> filters = new LinkedHashSet<>();
        driver.devices().forEach(d -> filters.add(d.availabilityTopic()));
        driver.decoders().forEach(d -> filters.add(d.map().topic()));
        if (!filters.isEmpty()) {
            w.subscribe(new ArrayList<>(filters), p.subscribeQos(), this::arrived, timeout);
        }
        sink.robotInfo(com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.objectNode()
                .put("broker", driver.host() + ":" + driver.port()).put("mqtt", p.version())
                .put("clientId", driver.clientId()));
    }

    /** Called on the client library's threads: hand the message to the reader, or count it if the queue is full. */
    private void arrived(String topic, byte[] payload, boolean retained) {
        if (!queue.offer(new Message(topic, payload))) {
            overflow.incrementAndGet();
        }
    }

    @Override
    public void readNext(ReadingSink sink) throws IOException {
        Message m;
        try {
            m = queue.poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted");
        }
        long dropped = overflow.getAndSet(0);
        if (dropped > 0) {
            sink.malformed(dropped + " message(s) dropped: more than queueMessages=" + driver.params().queueMessages()
                    + " waited to be decoded");
        }
        if (m == null) {
            Throwable t = lost;
            if (t != null || closed) {
                throw new IOException("the broker connection was lost: "
                        + (t == null ? "closed" : t.getMessage() == null ? t.toString() : t.getMessage()));
            }
            return;
        }
        decode(m, sink);
    }

    private void decode(Message m, ReadingSink sink) {
        for (DeviceSpec d : driver.devices()) {
            if (d.availabilityTopic().equals(m.topic())) {
                availability(d, new String(m.payload(), StandardCharsets.UTF_8).strip(), sink);
            }
        }
        List<String> unreadable = new ArrayList<>();
        List<ReadingDecoder> decoders = driver.decoders();
        for (int i = 0; i < decoders.size(); i++) {
            ReadingDecoder d = decoders.get(i);
            if (!d.map().filter().matches(m.topic())) {
                continue;
            }
            SessionChannel channel = channels.get(i);
            try {
                d.decode(m.payload()).ifPresent(v -> channel.publish(sink, v));
            } catch (IllegalArgumentException e) {
                unreadable.add("channel " + d.map().channel() + ": " + e.getMessage());
            }
        }
        if (!unreadable.isEmpty()) {
            // One malformed message counts once, however many channels it feeds.
            sink.malformed("message on " + m.topic() + " for " + String.join("; ", unreadable));
        }
    }

    private void availability(DeviceSpec d, String payload, ReadingSink sink) {
        String state = payload;
        if (payload.startsWith("{")) {
            // Zigbee2MQTT 2.x: {"state":"online"}
            try {
                state = JSON.readTree(payload).path("state").asText(payload);
            } catch (IOException e) {
                state = payload;
            }
        }
        boolean online;
        if (state.equals(d.online())) {
            online = true;
        } else if (state.equals(d.offline())) {
            online = false;
        } else {
            sink.malformed("availability of " + d.name() + " on " + d.availabilityTopic() + " is '"
                    + ReadingDecoder.abbreviate(payload) + "', neither '" + d.online() + "' nor '" + d.offline() + "'");
            return;
        }
        sink.device(d.name(), online, d.availabilityTopic() + " says " + state);
        devices.said(d, online, d.name() + " is offline (" + d.availabilityTopic() + " says " + state + ")");
        // A device's word changes what every device reached through it can do, so every channel is told again.
        for (ReadingDecoder r : driver.decoders()) {
            String device = r.map().device();
            if (!device.isEmpty()) {
                String why = devices.unreachable(device);
                sink.availability(r.map().channel(), why == null, why == null ? device + " is online" : why);
            }
        }
    }

    @Override
    public void write(String channel, Payload command) throws IOException {
        CommandMap c = driver.command(channel);
        if (c == null) {
            throw new IOException("the broker connection carries no command channel '" + channel + "'");
        }
        if (!c.device().isEmpty()) {
            String offline = devices.unreachable(c.device());
            if (offline != null) {
                throw new IllegalArgumentException("device " + c.device() + " cannot be reached: " + offline);
            }
        }
        String text = new PayloadTemplate(c.template()).render(command);
        MqttWire w = wire;
        if (w == null || lost != null) {
            throw new IOException("the broker connection is lost");
        }
        w.publish(c.topic(), text.getBytes(StandardCharsets.UTF_8), c.qos(), false);
    }

    @Override
    public void close() {
        closed = true;
        MqttWire w = wire;
        if (w != null) {
            w.disconnect();
        }
        if (overflow.get() > 0) {
            LOG.debug("{} message(s) were dropped at close", overflow.get());
        }
    }
}
