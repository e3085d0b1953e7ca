package org.habla.recording;

/** A file that is not a readable HABLA recording (not a damaged tail, which a reader reports as a {@link Cut}). */
public final class RecordingException extends Exception {

    public RecordingException(String message) {
        super(message);
    }
}
