package org.habla.drivers.mqtt;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import org.habla.plugin.Param;

/**
 * The params of an {@code mqtt} bridge: which sockets it publishes, which take actions from topics, and how to
 * log in to the broker.
 *
 * <pre>{@code
 * "bridges": [{"id": "home", "type": "mqtt", "address": "127.0.0.1:1883",
 *              "params": {"publish": ["occupancy", "light"], "actions": ["action"]}}]
 * }</pre>
 */
public record MqttBridgeParams(
        @Param(value = "the sockets whose samples are published on <baseTopic>/<system>/<socket>", defaultValue = "[]")
        List<String> publish,
        @Param(value = "the sockets that take actions from <baseTopic>/<system>/<socket>/set: the bridge's command "
                + "role; no other socket is written to", defaultValue = "[]") List<String> actions,
        @Param(value = "the first level of every topic", defaultValue = "\"habla\"") String baseTopic,
        @Param(value = "publish Home Assistant discovery configs (retained) so a home-automation system finds the "
                + "sockets", defaultValue = "true") boolean discovery,
        @Param(value = "Home Assistant's discovery prefix", defaultValue = "\"homeassistant\"") String discoveryPrefix,
        @Param(value = "at most this many samples a second per socket output; 0: every sample", unit = "Hz",
                defaultValue = "0", min = 0, max = 100_000) double maxHz,
        @Param(value = "how long the bridge keeps command of an actuating socket after its last action or take; "
                + "then the next commander to write takes it (a shorter safety.watchdogMs lapses it sooner)",
                unit = "ms", defaultValue = "5000", min = 1, max = MAX_HOLD_MS) int holdMs,
        @Param(value = "the client identifier; empty: habla-bridge- and the system's name", defaultValue = "\"\"")
        String clientId,
        @Param(value = "the user name to log in with; empty: none", defaultValue = "\"\"") String username,
        @Param(value = "the password; prefer passwordFile", defaultValue = "\"\"") String password,
        @Param(value = "a file whose first line is the password", defaultValue = "\"\"", file = true)
        String passwordFile,
        @Param(value = "connect with TLS (the default port is then 8883)", defaultValue = "false") boolean tls,
        @Param(value = "a PEM file of the certificate authorities that sign the broker's certificate; empty: the "
                + "JVM's trust store", defaultValue = "\"\"", file = true) String caFile) {

    /** The longest hold a bridge may keep on a socket: an hour. */
    static final int MAX_HOLD_MS = 3_600_000;
    private static final Pattern LEVEL = Pattern.compile("[A-Za-z0-9_-]{1,64}");

    public MqttBridgeParams {
        publish = List.copyOf(new LinkedHashSet<>(publish));
        actions = List.copyOf(new LinkedHashSet<>(actions));
        if (publish.isEmpty() && actions.isEmpty()) {
            throw new IllegalArgumentException("publish, actions: name at least one socket to carry");
        }
        if (!LEVEL.matcher(baseTopic).matches()) {
            throw new IllegalArgumentException("baseTopic must be one topic level of letters, digits, '_' or '-', was '"
                    + baseTopic + "'");
        }
        if (!LEVEL.matcher(discoveryPrefix).matches()) {
            throw new IllegalArgumentException("discoveryPrefix must be one topic level, was '" + discoveryPrefix + "'");
        }
        if (!password.isEmpty() && !passwordFile.isEmpty()) {
            throw new IllegalArgumentException("give password or passwordFile, not both");
        }
        if (!caFile.isEmpty() && !tls) {
            throw new IllegalArgumentException("caFile is for TLS: set \"tls\": true as well");
        }
    }

    /** Every socket named. */
    Set<String> sockets() {
        Set<String> all = new LinkedHashSet<>(publish);
        all.addAll(actions);
        return all;
    }
}
