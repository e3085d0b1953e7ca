package org.habla.driver;

import java.util.Objects;
import org.habla.sample.Payload;

/**
 * One reading channel as a session writes it: the handle is taken from the sink the first time the session writes
 * (the engine gives a link one sink for its life) and kept, so a reading costs no look-up by name. Belongs to the
 * session's reader thread, like the sink.
 *
 * <pre>{@code
 * private final SessionChannel sonar = new SessionChannel("sonar");
 * ...
 * sonar.publish(sink, VectorValue.wrap(ranges));
 * }</pre>
 */
public final class SessionChannel {

    private final String name;
    private ReadingSink sink;
    private ReadingSink.Channel handle;

    public SessionChannel(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    /** A reading taken now. */
    public void publish(ReadingSink to, Payload value) {
        handle(to).publish(value);
    }

    /** A reading taken at {@code sourceMicros} (microseconds since the epoch). */
    public void publish(ReadingSink to, Payload value, long sourceMicros) {
        handle(to).publish(value, sourceMicros);
    }

    private ReadingSink.Channel handle(ReadingSink to) {
        if (to != sink) {
            handle = to.channel(name);
            sink = to;
        }
        return handle;
    }

    @Override
    public String toString() {
        return "reading channel " + name;
    }
}
