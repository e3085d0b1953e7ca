package org.habla.method.builtin;

import java.util.Locale;
import org.habla.config.ParamsJson;
import org.habla.method.Delivery;
import org.habla.plugin.Param;

import org.habla.sample.PayloadKind;

/**
 * The params of the trivial methods {@code pass-through} and {@code channel}: what kind of value they
 * carry and how samples wait for them.
 */
public record RelayParams(
        @Param(value = "Payload kind carried: number, vector, text, record, audio, image or any",
                defaultValue = "\"any\"")
        String kind,
        @Param(value = "How samples wait: latest (newest wins) or queue (bounded first-in first-out)",
                defaultValue = "\"latest\"")
        String delivery,
        @Param(value = "Queue length when delivery is queue", defaultValue = "64", min = 1, max = Delivery.MAX_CAPACITY)
        int capacity) {

    public RelayParams {
        kind = kind.toLowerCase(Locale.ROOT);
        delivery = delivery.toLowerCase(Locale.ROOT);
        try {
            PayloadKind.fromWire(kind);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("kind: " + e.getMessage());
        }
        if (!delivery.equals("latest") && !delivery.equals("queue")) {
            throw new IllegalArgumentException("delivery must be latest or queue, was '" + delivery + "'");
        }
    }

    /** Every parameter at its default. */
    public static RelayParams defaults() {
        return ParamsJson.defaults(RelayParams.class);
    }

    public PayloadKind payloadKind() {
        return PayloadKind.fromWire(kind);
    }

    public Delivery inputDelivery() {
        return delivery.equals("queue") ? Delivery.queue(capacity) : Delivery.latest();
    }
}
