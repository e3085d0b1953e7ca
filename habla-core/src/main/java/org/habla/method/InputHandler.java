package org.habla.method;

import org.habla.sample.Payload;
import org.habla.sample.Sample;

/** Handles one sample of an input, with its payload already typed. */
@FunctionalInterface
public interface InputHandler<P extends Payload> {

    void handle(P payload, Sample sample) throws Exception;
}
