package org.habla.drivers.mqtt;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.net.ConnectException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;

/**
 * One MQTT client connection, whatever the protocol version: the little of an MQTT client that HABLA uses.
 * The client never reconnects by itself: a lost connection is reported once through {@code onLost}, and whoever
 * owns the wire makes a new one (the engine's back-off decides when).
 */
interface MqttWire {

    /**
     * What arrives on a subscription: the topic, the raw payload, and whether the broker kept it (a retained message
     * handed to a new subscriber). Called on the client library's threads.
     */
    @FunctionalInterface
    interface Listener {
        void message(String topic, byte[] payload, boolean retained);
    }

    /** Connects and logs in. */
    void connect(Duration timeout) throws IOException;

    /** Subscribes to every filter and waits for the broker's acknowledgement. */
    void subscribe(List<String> filters, int qos, Listener listener, Duration timeout) throws IOException;

    /**
     * Sends a message without waiting for the broker's acknowledgement; failures are logged by the wire. The future
     * completes when the message is sent (QoS 0) or acknowledged, or fails.
     */
    CompletableFuture<?> publish(String topic, byte[] payload, int qos, boolean retain);

    /** Disconnects politely (the broker then does not publish the will); safe to call twice. */
    void disconnect();

    /** A wire to {@code endpoint} that calls {@code onLost} once if the connection ends without {@link #disconnect}. */
    static MqttWire to(BrokerEndpoint endpoint, Consumer<Throwable> onLost) {
        return endpoint.version() == BrokerEndpoint.MqttVersion.V5 ? new Mqtt5Wire(endpoint, onLost)
                : new Mqtt3Wire(endpoint, onLost);
    }

    /** Waits for a library future, turning its failure or a time-out into an {@link IOException}. */
    static <T> T await(CompletableFuture<T> future, Duration timeout, String what) throws IOException {
        try {
            return future.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            future.cancel(true);
            throw new IOException(what + " took longer than " + timeout.toMillis() + " ms");
        } catch (ExecutionException e) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            for (Throwable c = cause; c != null; c = c.getCause()) {
                if (c instanceof ConnectException refused) {
                    // The broker's host answered that nothing listens: said as such, so the engine's back-off
                    // treats it as an answer (a broker restarting) and tries again soon, without doubling.
                    ConnectException plain = new ConnectException(what + " failed: " + refused.getMessage());
                    plain.initCause(cause);
                    throw plain;
                }
            }
            throw new IOException(what + " failed: " + (cause.getMessage() == null ? cause : cause.getMessage()), cause);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException(what + " interrupted");
        }
    }
}
