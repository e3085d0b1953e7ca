package org.habla.drivers.mqtt;

import com.hivemq.client.mqtt.MqttClient;
import com.hivemq.client.mqtt.MqttClientSslConfigBuilder;
import com.hivemq.client.mqtt.MqttGlobalPublishFilter;
import com.hivemq.client.mqtt.datatypes.MqttQos;
import com.hivemq.client.mqtt.lifecycle.MqttDisconnectSource;
import com.hivemq.client.mqtt.mqtt5.Mqtt5AsyncClient;
import com.hivemq.client.mqtt.mqtt5.Mqtt5ClientBuilder;
import com.hivemq.client.mqtt.mqtt5.message.connect.Mqtt5ConnectBuilder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** An {@link MqttWire} that speaks MQTT 5. */
final class Mqtt5Wire implements MqttWire {

    private static final Logger LOG = LoggerFactory.getLogger(Mqtt5Wire.class);

    private final BrokerEndpoint endpoint;
    private final Mqtt5AsyncClient client;
    private final AtomicBoolean ended = new AtomicBoolean();
    private volatile Listener listener = (topic, payload, retained) -> { };

    Mqtt5Wire(BrokerEndpoint endpoint, Consumer<Throwable> onLost) {
        this.endpoint = endpoint;
        Mqtt5ClientBuilder b = MqttClient.builder().identifier(endpoint.clientId())
                .serverHost(endpoint.host()).serverPort(endpoint.port()).useMqttVersion5()
                .addDisconnectedListener(context -> {
                    if (context.getSource() != MqttDisconnectSource.USER && ended.compareAndSet(false, true)) {
                        onLost.accept(context.getCause());
                    }
                });
        if (endpoint.tls().isPresent()) {
            MqttClientSslConfigBuilder.Nested<? extends Mqtt5ClientBuilder> ssl = b.sslConfig();
            if (endpoint.tls().get().trust() != null) {
                ssl = ssl.trustManagerFactory(endpoint.tls().get().trust());
            }
            b = ssl.applySslConfig();
        }
        this.client = b.buildAsync();
        client.publishes(MqttGlobalPublishFilter.ALL, p -> listener.message(p.getTopic().toString(), p.getPayloadAsBytes(),
                p.isRetain()));
    }

    @Override
    public void connect(Duration timeout) throws IOException {
        Mqtt5ConnectBuilder.Send<? extends CompletableFuture<?>> c = client.connectWith()
                .cleanStart(true).keepAlive(endpoint.keepAliveS());
        if (!endpoint.username().isEmpty()) {
            c = c.simpleAuth().username(endpoint.username())
                    .password(endpoint.password().getBytes(StandardCharsets.UTF_8)).applySimpleAuth();
        }
        if (endpoint.will().isPresent()) {
            BrokerEndpoint.Will w = endpoint.will().get();
            c = c.willPublish().topic(w.topic()).payload(w.payload()).qos(MqttQos.AT_LEAST_ONCE).retain(w.retain())
                    .applyWillPublish();
        }
        MqttWire.await(c.send(), timeout, "connecting to the broker at " + endpoint.host() + ":" + endpoint.port());
    }

    @Override
    public void subscribe(List<String> filters, int qos, Listener onMessage, Duration timeout) throws IOException {
        this.listener = onMessage;
        List<CompletableFuture<?>> acks = new ArrayList<>();
        for (String f : filters) {
            acks.add(client.subscribeWith().topicFilter(f).qos(MqttQos.fromCode(qos)).send());
        }
        for (int i = 0; i < acks.size(); i++) {
            MqttWire.await(acks.get(i), timeout, "subscribing to " + filters.get(i));
        }
    }

    @Override
    public CompletableFuture<?> publish(String topic, byte[] payload, int qos, boolean retain) {
        return client.publishWith().topic(topic).qos(MqttQos.fromCode(qos)).retain(retain).payload(payload).send()
                .whenComplete((result, error) -> {
                    if (error != null) {
                        LOG.debug("publishing on {} failed: {}", topic, error.toString());
                    }
                });
    }

    @Override
    public void disconnect() {
        if (ended.compareAndSet(false, true)) {
            client.disconnect().whenComplete((r, e) -> { });
        }
    }
}
