package org.habla.methods.notes;

import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code note-recognition} method: which notes, how clear and how long. */
public record NoteRecognitionParams(
        @Param(value = "Notes to recognise, e.g. [\"C5\",\"E5\",\"G5\",\"C6\"]; empty: every note in the range",
                defaultValue = "[]")
        List<String> notes,
        @Param(value = "How long a note must sound before it is reported", unit = "ms", defaultValue = "150",
                min = 10, max = 10_000)
        double minDurationMs,
        @Param(value = "Frequency of A4, the tuning reference", unit = "Hz", defaultValue = "440", min = 400, max = 480)
        double referenceA4Hz,
        @Param(value = "How far the spectral peak must stand above the median of the range", unit = "dB",
                defaultValue = "15", min = 3, max = 80)
        double minSnrDb,
        @Param(value = "Largest distance from the nearest note still called that note", unit = "cents",
                defaultValue = "40", min = 1, max = 50)
        double toleranceCents,
        @Param(value = "Lowest frequency searched for a tone", unit = "Hz", defaultValue = "100", min = 20, max = 8000)
        double minHz,
        @Param(value = "Highest frequency searched for a tone", unit = "Hz", defaultValue = "4500",
                min = 40, max = 12_000)
        double maxHz,
        @Param(value = "Length of one analysis frame", unit = "ms", defaultValue = "64", min = 8, max = 500)
        double frameMs,
        @Param(value = "Step between frames", unit = "ms", defaultValue = "16", min = 1, max = 500)
        double hopMs,
        @Param(value = "Longest gap inside one note (a masked frame or two) that does not end it", unit = "ms",
                defaultValue = "50", min = 0, max = 5000)
        double maxDropoutMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "256", min = 1, max = 65_536)
        int queue) {

    public NoteRecognitionParams {
        notes = List.copyOf(notes);
        notes.forEach(Note::parse);
        if (!(maxHz > minHz)) {
            throw new IllegalArgumentException("maxHz (" + maxHz + ") must be above minHz (" + minHz + ")");
        }
        if (hopMs > frameMs) {
            throw new IllegalArgumentException("hopMs (" + hopMs + ") must not exceed frameMs (" + frameMs + ")");
        }
    }

    /** Every parameter at its default. */
    public static NoteRecognitionParams defaults() {
        return ParamsJson.defaults(NoteRecognitionParams.class);
    }

    /** The allowed notes; empty means every note. */
    public Set<Note> allowedNotes() {
        return notes.stream().map(Note::parse).collect(Collectors.toUnmodifiableSet());
    }
}
