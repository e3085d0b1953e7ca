package org.habla.replay;

import java.util.List;
import java.util.Optional;
import org.habla.recording.Cut;

/**
 * What a replay did and how its outputs compare with the recording.
 *
 * @param readings       recorded readings fed into the interface channels
 * @param controlWrites  recorded control writes replayed; {@code rejected} of them were refused by the method
 * @param rejected       control writes the method refused in the replay
 * @param ticks          periodic tasks run (method ticks, heartbeats, the watchdog)
 * @param unsettled      events after which the graph did not go idle within the settle time
 * @param recordedMicros the span of the recording, in its own clock's microseconds
 * @param wallMillis     how long the replay took
 * @param streams        each exposed output and the hardware commands, compared with the recording
 * @param cut            where the recording was cut (a daemon killed while recording), if it was
 * @param complete       whether the recording ended cleanly
 * @param recordedDrops  events the recorder itself had dropped (a writer that fell behind)
 */
public record ReplayResult(long readings, long controlWrites, long rejected, long ticks, long unsettled,
        long recordedMicros, long wallMillis, List<StreamMatch> streams, Optional<Cut> cut, boolean complete,
        long recordedDrops) {

    public ReplayResult {
        streams = List.copyOf(streams);
    }

    /** The comparison of one stream ({@code method.output} or {@code commands}); empty if neither side had it. */
    public Optional<StreamMatch> stream(String name) {
        return streams.stream().filter(s -> s.name().equals(name)).findFirst();
    }
}
