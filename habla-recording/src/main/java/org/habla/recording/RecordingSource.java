package org.habla.recording;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * A recording read event by event, whatever its format: MCAP ({@code .mcap}, {@link McapRecordingReader}) or
 * HABLA's line format ({@link RecordingReader}). Reading stops at the first record that is not whole or is
 * damaged; {@link #cut} says where and why.
 */
public interface RecordingSource extends AutoCloseable {

    /** Opens a recording, MCAP or line format as its first bytes say, and reads its header. */
    static RecordingSource open(Path file) throws IOException, RecordingException {
        return McapRecordingReader.isMcap(file) ? McapRecordingReader.open(file) : RecordingReader.open(file);
    }

    /** Reads a whole recording into memory: its header, its events, and where it was cut, if it was. */
    static Recording readAll(Path file) throws IOException, RecordingException {
        try (RecordingSource s = open(file)) {
            java.util.List<RecordedEvent> events = new java.util.ArrayList<>();
            for (RecordedEvent e = s.next(); e != null; e = s.next()) {
                events.add(e);
            }
            return new Recording(s.header(), events, s.cut());
        }
    }

    RecordingHeader header();

    /** The next event, or null after the last whole one. */
    RecordedEvent next() throws IOException;

    /** Where the readable part ended before the end of the file; empty if every byte was read. */
    Optional<Cut> cut();

    @Override
    void close() throws IOException;
}
