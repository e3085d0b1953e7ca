package org.habla.drivers.mqtt;

import java.util.Objects;
import java.util.Optional;
import javax.net.ssl.TrustManagerFactory;

/**
 * Where a broker is and how to log in: what every MQTT connection HABLA opens needs.
 *
 * @param host       the broker's host
 * @param port       the broker's port (1883, or 8883 with TLS, unless the address says otherwise)
 * @param version    the MQTT protocol version
 * @param clientId   the client identifier; unique per broker
 * @param username   empty for none
 * @param password   empty for none
 * @param tls        the trust to verify the broker's certificate with; empty for a plain TCP connection. Present
 *                   with a null factory: TLS with the JVM's default trust
 * @param keepAliveS how often the client and the broker check each other when nothing else flows; a broker that
 *                   stops answering is declared lost after about 1.5 times this
 * @param will       what the broker publishes for this client when it loses it (e.g. an availability topic)
 */
record BrokerEndpoint(String host, int port, MqttVersion version, String clientId, String username, String password,
        Optional<Tls> tls, int keepAliveS, Optional<Will> will) {

    BrokerEndpoint {
        Objects.requireNonNull(host, "host");
        Objects.requireNonNull(version, "version");
        Objects.requireNonNull(clientId, "clientId");
        username = username == null ? "" : username;
        password = password == null ? "" : password;
        Objects.requireNonNull(tls, "tls");
        Objects.requireNonNull(will, "will");
    }

    /** TLS settings: the trust for the broker's certificate (null: the JVM's default trust store). */
    record Tls(TrustManagerFactory trust) {
    }

    /** A last will: a message the broker publishes when it loses this client. */
    record Will(String topic, byte[] payload, boolean retain) {
    }

    enum MqttVersion {
        V3_1_1("3.1.1"), V5("5");

        private final String configName;

        MqttVersion(String configName) {
            this.configName = configName;
        }

        String configName() {
            return configName;
        }

        static MqttVersion fromConfig(String text) {
            for (MqttVersion v : values()) {
                if (v.configName.equals(text)) {
                    return v;
                }
            }
            throw new IllegalArgumentException("version must be \"3.1.1\" or \"5\", was '" + text + "'");
        }
    }
}
