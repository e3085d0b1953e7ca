package org.habla.methods.notes;

import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code note-recognition} method: which notes, how clear and how long. */
public record NoteRecognitionParams(
        @Param(value = "Notes to recognise, e.g. [\"C5\",\"E5\",\"G5\",\"C6\"]; empty: every note in the range",
                defaultValue = "[]")
        List<String> notes,
        @Param(value = "How long a note must sound before it is reported", unit = "ms", defaultValue = "150")
        Double minDurationMs,
        @Param(value = "Frequency of A4, the tuning reference", unit = "Hz", defaultValue = "440")
        Double referenceA4Hz,
        @Param(value = "How far the spectral peak must stand above the median of the range", unit = "dB",
                defaultValue = "15")
        Double minSnrDb,
        @Param(value = "Largest distance from the nearest note still called that note", unit = "cents",
                defaultValue = "40")
        Double toleranceCents,
        @Param(value = "Lowest frequency searched for a tone", unit = "Hz", defaultValue = "100")
        Double minHz,
        @Param(value = "Highest frequency searched for a tone", unit = "Hz", defaultValue = "4500")
        Double maxHz,
        @Param(value = "Length of one analysis frame", unit = "ms", defaultValue = "64")
        Double frameMs,
        @Param(value = "Step between frames", unit = "ms", defaultValue = "16")
        Double hopMs,
        @Param(value = "Longest gap inside one note (a masked frame or two) that does not end it", unit = "ms",
                defaultValue = "50")
        Double maxDropoutMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "256")
        Integer queue) {

    public NoteRecognitionParams {
        notes = List.copyOf(ParamDefaults.or(NoteRecognitionParams.class, "notes", notes));
        notes.forEach(Note::parse);
        minDurationMs = ParamRules.within(NoteRecognitionParams.class, "minDurationMs", minDurationMs, 10, 10_000);
        referenceA4Hz = ParamRules.within(NoteRecognitionParams.class, "referenceA4Hz", referenceA4Hz, 400, 480);
        minSnrDb = ParamRules.within(NoteRecognitionParams.class, "minSnrDb", minSnrDb, 3, 80);
        toleranceCents = ParamRules.within(NoteRecognitionParams.class, "toleranceCents", toleranceCents, 1, 50);
        minHz = ParamRules.within(NoteRecognitionParams.class, "minHz", minHz, 20, 8000);
        maxHz = ParamRules.within(NoteRecognitionParams.class, "maxHz", maxHz, 40, 12_000);
        if (!(maxHz > minHz)) {
            throw new IllegalArgumentException("maxHz (" + maxHz + ") must be above minHz (" + minHz + ")");
        }
        frameMs = ParamRules.within(NoteRecognitionParams.class, "frameMs", frameMs, 8, 500);
        hopMs = ParamRules.within(NoteRecognitionParams.class, "hopMs", hopMs, 1, 500);
        if (hopMs > frameMs) {
            throw new IllegalArgumentException("hopMs (" + hopMs + ") must not exceed frameMs (" + frameMs + ")");
        }
        maxDropoutMs = ParamRules.within(NoteRecognitionParams.class, "maxDropoutMs", maxDropoutMs, 0, 5000);
        queue = ParamRules.within(NoteRecognitionParams.class, "queue", queue, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static NoteRecognitionParams defaults() {
        return new NoteRecognitionParams(null, null, null, null, null, null, null, null, null, null, null);
    }

    /** The allowed notes; empty means every note. */
    public Set<Note> allowedNotes() {
        return notes.stream().map(Note::parse).collect(Collectors.toUnmodifiableSet());
    }
}
