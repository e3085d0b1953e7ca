package org.habla.daemon;

import java.io.IOException;
import java.util.List;

/** The config places a method on a worker that says it cannot run it; the daemon does not start. */
public final class PlacementRefusedException extends IOException {

    private final List<String> refusals;

    public PlacementRefusedException(List<String> refusals) {
        super(String.join("; ", refusals));
        this.refusals = List.copyOf(refusals);
    }

    /** One sentence per refused method. */
    public List<String> refusals() {
        return refusals;
    }
}
