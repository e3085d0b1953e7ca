package org.habla.graph;

import java.util.Objects;
import org.habla.method.Shape;

/**
 * One output of a running method, as an observer of the graph sees it (a monitor, a live viewer).
 *
 * @param methodId the method's id in the config
 * @param output   the output's name
 * @param shape    what its values look like
 */
public record OutputInfo(String methodId, String output, Shape shape) {

    public OutputInfo {
        Objects.requireNonNull(methodId, "methodId");
        Objects.requireNonNull(output, "output");
        Objects.requireNonNull(shape, "shape");
    }

    /** The producer name its samples carry: {@code methodId.output}. */
    public String producer() {
        return methodId + "." + output;
    }
}
