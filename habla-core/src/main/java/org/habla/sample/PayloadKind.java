package org.habla.sample;

import java.util.Locale;

/** The kinds of payload a sample can carry; {@link #ANY} is accepted by ports that take every kind. */
public enum PayloadKind {
    NUMBER(NumberValue.class),
    VECTOR(VectorValue.class),
    TEXT(TextValue.class),
    RECORD(RecordValue.class),
    AUDIO(AudioChunk.class),
    IMAGE(ImageFrame.class),
    ANY(Payload.class);

    private final Class<? extends Payload> type;

    PayloadKind(Class<? extends Payload> type) {
        this.type = type;
    }

    /** The payload class carried by this kind ({@code Payload} itself for {@link #ANY}). */
    public Class<? extends Payload> type() {
        return type;
    }

    /** The lower-case name used in configs and on the wire. */
    public String wireName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Whether a value of kind {@code produced} may be delivered to a port of this kind. */
    public boolean accepts(PayloadKind produced) {
        return this == ANY || produced == ANY || this == produced;
    }

    public static PayloadKind of(Class<? extends Payload> type) {
        for (PayloadKind k : values()) {
            if (k.type == type) {
                return k;
            }
        }
        throw new IllegalArgumentException("not a payload class: " + type.getName());
    }

    /** Parses a wire name such as {@code "vector"}; throws with the accepted names when unknown. */
    public static PayloadKind fromWire(String name) {
        for (PayloadKind k : values()) {
            if (k.wireName().equals(name)) {
                return k;
            }
        }
        throw new IllegalArgumentException("unknown payload kind '" + name
                + "' (expected one of number, vector, text, record, audio, image, any)");
    }
}
