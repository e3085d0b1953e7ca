package org.habla.sample;

import java.util.Objects;

/** A piece of text (a recognised word, a command label, a phrase to say). */
public record TextValue(String text) implements Payload {

    public TextValue {
        Objects.requireNonNull(text, "text");
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.TEXT;
    }
}
