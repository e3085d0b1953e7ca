package org.habla.drivers.mqtt;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.ClientConnection;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;

/**
 * Devices on an MQTT broker as one interface: each reading map is a reading channel, each command map a command
 * channel, all over one client connection that the engine keeps ({@code broker}).
 */
final class MqttDriver implements Driver {

    /** The broker's port when the address names none. */
    static final int DEFAULT_PORT = 1883;
    /** The broker's TLS port when the address names none. */
    static final int DEFAULT_TLS_PORT = 8883;

    private final String host;
    private final int port;
    private final MqttParams params;
    private final String clientId;
    private final List<ReadingDecoder> decoders = new ArrayList<>();
    private final Map<String, CommandMap> commands = new LinkedHashMap<>();
    private final List<ChannelDescriptor> channels = new ArrayList<>();

    MqttDriver(InterfaceAddress address, MqttParams params) {
        this.host = address.host();
        this.port = address.portOr(params.tls() ? DEFAULT_TLS_PORT : DEFAULT_PORT);
        this.params = params;
        this.clientId = params.clientId().isEmpty()
                ? "habla-" + UUID.randomUUID().toString().substring(0, 8) : params.clientId();
        for (ReadingMap r : params.readings()) {
            decoders.add(new ReadingDecoder(r));
            channels.add(r.descriptor());
        }
        for (CommandMap c : params.commands()) {
            commands.put(c.channel(), c);
            channels.add(c.descriptor());
        }
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return List.copyOf(channels);
    }

    @Override
    public List<Connection> connections() {
        return List.of();
    }

    @Override
    public List<ClientConnection> clientConnections() {
        return List.of(new ClientConnection("broker", commands.keySet(), () -> new MqttSession(this)));
    }

    String host() {
        return host;
    }

    int port() {
        return port;
    }

    String clientId() {
        return clientId;
    }

    MqttParams params() {
        return params;
    }

    List<ReadingDecoder> decoders() {
        return decoders;
    }

    List<DeviceSpec> devices() {
        return params.devices();
    }

    CommandMap command(String channel) {
        return commands.get(channel);
    }
}
