package org.habla.method.builtin;

import java.util.Locale;
import org.habla.method.Delivery;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.sample.PayloadKind;

/**
 * The params of the trivial methods {@code pass-through} and {@code channel}: what kind of value they
 * carry and how samples wait for them.
 */
public record RelayParams(
        @Param(value = "Payload kind carried: number, vector, text, record, audio, image or any", defaultValue = "\"any\"")
        String kind,
        @Param(value = "How samples wait: latest (newest wins) or queue (bounded first-in first-out)",
                defaultValue = "\"latest\"")
        String delivery,
        @Param(value = "Queue length when delivery is queue", defaultValue = "64")
        Integer capacity) {

    public RelayParams {
        kind = ParamDefaults.or(RelayParams.class, "kind", kind).toLowerCase(Locale.ROOT);
        delivery = ParamDefaults.or(RelayParams.class, "delivery", delivery).toLowerCase(Locale.ROOT);
        capacity = ParamDefaults.or(RelayParams.class, "capacity", capacity);
        try {
            PayloadKind.fromWire(kind);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("kind: " + e.getMessage());
        }
        if (!delivery.equals("latest") && !delivery.equals("queue")) {
            throw new IllegalArgumentException("delivery must be latest or queue, was '" + delivery + "'");
        }
        if (capacity < 1 || capacity > Delivery.MAX_CAPACITY) {
            throw new IllegalArgumentException("capacity must be in 1.." + Delivery.MAX_CAPACITY + ", was " + capacity);
        }
    }

    /** Every parameter at its default. */
    public static RelayParams defaults() {
        return new RelayParams(null, null, null);
    }

    public PayloadKind payloadKind() {
        return PayloadKind.fromWire(kind);
    }

    public Delivery inputDelivery() {
        return delivery.equals("queue") ? Delivery.queue(capacity) : Delivery.latest();
    }
}
