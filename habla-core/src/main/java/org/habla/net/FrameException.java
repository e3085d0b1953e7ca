package org.habla.net;

import java.io.IOException;

/**
 * A frame or a value that breaks the HABLA wire protocol, with the error code the peer is told
 * ({@code line_too_long}, {@code bad_json}, {@code bad_value}, ...).
 *
 * <p>A <em>recoverable</em> error has already been skipped: the stream is back at the start of the next
 * frame, so the connection goes on. A <em>fatal</em> one leaves the stream out of step (a binary block
 * too large to skip, a peer gone mid-frame): the connection must be closed after telling the peer.
 *
 * <p>It carries no stack trace: it reports what a peer sent, not where HABLA went wrong, and a peer sending
 * garbage causes thousands a second.
 */
public final class FrameException extends IOException {

    private static final long serialVersionUID = 1L;

    private final String code;
    private final boolean fatal;

    private FrameException(String code, String message, boolean fatal) {
        super(message);
        this.code = code;
        this.fatal = fatal;
    }

    /** An error after which the next frame can still be read. */
    public static FrameException recoverable(String code, String message) {
        return new FrameException(code, message, false);
    }

    /** An error after which the connection cannot go on. */
    public static FrameException fatal(String code, String message) {
        return new FrameException(code, message, true);
    }

    /** A value that does not fit where it was sent. */
    public static FrameException badValue(String message) {
        return new FrameException("bad_value", message, false);
    }

    @Override
    public synchronized Throwable fillInStackTrace() {
        return this;
    }

    /** The wire error code. */
    public String code() {
        return code;
    }

    public boolean fatal() {
        return fatal;
    }
}
