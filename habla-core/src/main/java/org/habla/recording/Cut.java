package org.habla.recording;

/**
 * Where a recording stops being readable: a last record torn by a kill, or damage. Every whole record
 * before {@code offset} was read; the {@code ignoredBytes} from there on were not.
 *
 * @param offset       the byte offset of the first record that is not whole
 * @param ignoredBytes the bytes from {@code offset} to the end of the file
 * @param reason       what was wrong with it ("the header line has no end", "the binary block is short", ...)
 */
public record Cut(long offset, long ignoredBytes, String reason) {
}
