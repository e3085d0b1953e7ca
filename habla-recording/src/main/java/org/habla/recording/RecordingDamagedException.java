package org.habla.recording;

/**
 * A recording damaged before its end (not torn by a kill): a replay of it would silently stop at the damage,
 * so it is refused unless the user asks to salvage the part before it.
 */
public final class RecordingDamagedException extends RecordingException {

    private final Cut cut;

    public RecordingDamagedException(Cut cut) {
        super(cut.describe());
        this.cut = cut;
    }

    /** Where the damage is. */
    public Cut cut() {
        return cut;
    }
}
