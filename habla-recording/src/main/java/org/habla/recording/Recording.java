package org.habla.recording;

import java.util.List;
import java.util.Optional;

/**
 * A recording read into memory.
 *
 * @param header the config and channels it was made with
 * @param events every whole record after the header, in file order
 * @param cut    where the file stopped being readable, if it did (a torn end, or damage)
 */
public record Recording(RecordingHeader header, List<RecordedEvent> events, Optional<Cut> cut) {

    public Recording {
        events = List.copyOf(events);
    }

    /** The events of one type, in order. */
    public <T extends RecordedEvent> List<T> events(Class<T> type) {
        return events.stream().filter(type::isInstance).map(type::cast).toList();
    }

    /** Whether the recording was closed cleanly (it ends with an end record). */
    public boolean complete() {
        return !events.isEmpty() && events.get(events.size() - 1) instanceof RecordedEvent.End;
    }
}
