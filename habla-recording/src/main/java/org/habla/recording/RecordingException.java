package org.habla.recording;

/**
 * A file that is not a readable HABLA recording, or one a replay refuses because it is damaged (a torn tail is
 * not an error: a reader reports it as a {@link Cut}).
 */
public class RecordingException extends Exception {

    public RecordingException(String message) {
        super(message);
    }
}
