package org.habla.config;

/**
 * The limits every socket enforces; each is named in the error a client gets when it crosses it.
 *
 * @param maxLineBytes       the longest JSON line accepted, newline excluded
 * @param maxBinaryBytes     the largest {@code "bytes"} block accepted after a line
 * @param maxClientsPerPort  control clients at once on one method's port; the next is refused with an error line
 * @param clientQueueSamples samples waiting for one slow client before the oldest are dropped (and counted)
 */
public record Limits(int maxLineBytes, int maxBinaryBytes, int maxClientsPerPort, int clientQueueSamples) {

    public static final Limits DEFAULTS = new Limits(65_536, 8 * 1024 * 1024, 16, 256);
}
