package org.habla.recording;

import java.util.OptionalLong;

/**
 * Where a recording stops being readable. Every whole record before {@code offset} was read; the
 * {@code ignoredBytes} from there on were not.
 *
 * <p>A <b>torn end</b> is what a daemon killed mid-write leaves: the file ends inside its last record, and no
 * whole record follows. Anything else is <b>damage</b>: a record that is complete but unreadable (a line that is
 * not JSON, a block size no recorder writes), or a cut after which whole records follow — the file was changed
 * or broken in the middle, and what follows the damage is lost to a reader that stops there.
 *
 * @param offset       the byte offset of the first record that is not whole
 * @param ignoredBytes the bytes from {@code offset} to the end of the file
 * @param reason       what was wrong with it ("the header line has no end", "the binary block is short", ...)
 * @param damage       whether this is damage rather than a torn end
 * @param nextWholeRecord the offset of the first whole record after {@code offset}, if there is one
 */
public record Cut(long offset, long ignoredBytes, String reason, boolean damage, OptionalLong nextWholeRecord) {

    /** A torn end: the file ends inside the record at {@code offset}. */
    public static Cut tornEnd(long offset, long ignoredBytes, String reason) {
        return new Cut(offset, ignoredBytes, reason, false, OptionalLong.empty());
    }

    /** Whether this is a torn end (a kill mid-write), which a replay takes as the end of the recording. */
    public boolean torn() {
        return !damage;
    }

    /** One sentence for users: where, why, and what is beyond it. */
    public String describe() {
        if (torn()) {
            return "the recording ends in a torn record at byte " + offset + " (" + reason + ")";
        }
        return "the recording is damaged at byte " + offset + " (" + reason + "): the " + ignoredBytes
                + " bytes from there to the end are not read" + (nextWholeRecord.isPresent()
                ? ", and a whole record follows at byte " + nextWholeRecord.getAsLong() : "");
    }
}
