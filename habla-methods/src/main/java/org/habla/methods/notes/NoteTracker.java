package org.habla.methods.notes;

import java.util.Optional;

/**
 * Turns the note heard in each frame into note events: a note becomes an event once it has been
 * heard for the minimum duration, and is reported once; the event lasts while the same note keeps
 * being heard, across dropouts no longer than {@code maxDropoutMs} (a noise burst masking a frame
 * or two). A different note starts a new event at once.
 */
final class NoteTracker {

    private final double hopMs;
    private final double frameMs;
    private final double minDurationMs;
    private final double maxDropoutMs;
    private Note current;
    private double heardMs;
    private double dropoutMs;
    private boolean reported;

    NoteTracker(double hopMs, double frameMs, double minDurationMs, double maxDropoutMs) {
        this.hopMs = hopMs;
        this.frameMs = frameMs;
        this.minDurationMs = minDurationMs;
        this.maxDropoutMs = maxDropoutMs;
    }

    /** Takes the next frame's note (or none); returns a note when an event starts with this frame. */
    Optional<Note> next(Optional<Note> heard) {
        if (heard.isPresent() && heard.get().equals(current)) {
            heardMs += hopMs;
            dropoutMs = 0;
        } else if (heard.isPresent()) {
            current = heard.get();
            heardMs = frameMs;
            dropoutMs = 0;
            reported = false;
        } else if (current != null) {
            dropoutMs += hopMs;
            if (dropoutMs > maxDropoutMs) {
                current = null;
            }
            return Optional.empty();
        }
        if (current != null && !reported && heardMs >= minDurationMs) {
            reported = true;
            return Optional.of(current);
        }
        return Optional.empty();
    }
}
