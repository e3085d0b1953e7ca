package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.io.IOException;
import java.net.ConnectException;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;

class MqttWireTest {

    @Test
    void aBrokerThatRefusesTheConnectIsReportedAsARefusalWhateverTheLibraryWrappedItIn() {
        // The client library reports a refused connect inside its own exception; the engine's back-off must see
        // a ConnectException that says "refused", or it doubles its wait while a broker restarts.
        CompletableFuture<Object> failed = CompletableFuture.failedFuture(
                new RuntimeException("connect failed", new ConnectException("Connection refused: /127.0.0.1:1883")));
        Throwable thrown = catchThrowable(() -> MqttWire.await(failed, Duration.ofSeconds(1), "connecting"));
        assertThat(thrown).isInstanceOf(ConnectException.class);
        assertThat(thrown.getMessage()).contains("connecting failed").contains("refused");
    }

    @Test
    void otherFailuresStayPlainIoErrors() {
        CompletableFuture<Object> failed = CompletableFuture.failedFuture(new RuntimeException("not authorized"));
        Throwable thrown = catchThrowable(() -> MqttWire.await(failed, Duration.ofSeconds(1), "connecting"));
        assertThat(thrown).isInstanceOf(IOException.class).isNotInstanceOf(ConnectException.class);
        assertThat(thrown.getMessage()).isEqualTo("connecting failed: not authorized");
    }
}
