package org.habla.sample;

import java.util.Objects;

/**
 * One message in the method graph.
 *
 * @param payload        the value
 * @param producer       who made it: {@code "methodId.output"}, {@code "@interface.channel"} or {@code "control:socket"}
 * @param sequence       the producer's running count, from 1
 * @param sourceMicros   when the raw reading this sample derives from was taken, in microseconds since the
 *                       epoch; carried unchanged through the layers so latency is measurable at the socket
 * @param stale          true while a hardware link this sample depends on is down
 */
public record Sample(Payload payload, String producer, long sequence, long sourceMicros, boolean stale) {

    public Sample {
        Objects.requireNonNull(payload, "payload");
        Objects.requireNonNull(producer, "producer");
    }

    public PayloadKind kind() {
        return payload.kind();
    }
}
