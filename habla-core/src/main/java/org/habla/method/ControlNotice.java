package org.habla.method;

import java.util.Objects;
import org.habla.sample.RecordValue;

/**
 * Something a method tells the control clients whose values reach it — that a move they asked for was vetoed,
 * for instance — sent on their sockets as a {@code notice} line. It carries the source time of the message the
 * method was handling, which for a value written by a client is the time of that write: a client matches the
 * notice with its write by that {@code t} (the accepted value's echo carries the same).
 *
 * @param notice       what kind of notice ({@code veto}), a word clients switch on
 * @param methodId     the method that tells it
 * @param message      one sentence for a person: what happened and why, with the limit that decided it
 * @param detail       the same as fields a program reads (the reason, the limit, the value measured)
 * @param sourceMicros the source time of the message the method was handling
 */
public record ControlNotice(String notice, String methodId, String message, RecordValue detail, long sourceMicros) {

    public ControlNotice {
        Objects.requireNonNull(notice, "notice");
        Objects.requireNonNull(methodId, "methodId");
        Objects.requireNonNull(message, "message");
        Objects.requireNonNull(detail, "detail");
    }
}
