package org.habla.drivers.tekkotsu;

import java.io.EOFException;
import java.io.IOException;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Optional;

/**
 * Reads {@code \n}-terminated lines of a Tekkotsu text server, at most {@link #maxBytes} a line; a longer
 * line is cut and reported through {@link Line#truncated()}. The servers read this way (controller,
 * emergency stop) are quiet connections: a read waits as long as the server is silent.
 */
final class LineReader {

    private final int maxBytes;
    private final ByteArrayOutputStream partial = new ByteArrayOutputStream();
    private boolean overflowed;

    /** A line without its {@code \n} (and without a trailing {@code \r}). */
    record Line(String text, boolean truncated) {
    }

    LineReader(int maxBytes) {
        this.maxBytes = maxBytes;
    }

    /** The next line. */
    Optional<Line> next(InputStream in, String server) throws IOException {
        while (true) {
            int b = in.read();
            if (b < 0) {
                throw new EOFException("the " + server + " closed the connection");
            }
            if (b == '\n') {
                String text = partial.toString(StandardCharsets.ISO_8859_1);
                if (text.endsWith("\r")) {
                    text = text.substring(0, text.length() - 1);
                }
                Line line = new Line(text, overflowed);
                partial.reset();
                overflowed = false;
                return Optional.of(line);
            }
            if (partial.size() < maxBytes) {
                partial.write(b);
            } else {
                overflowed = true;
            }
        }
    }

    /** At most 60 characters of {@code text}, for messages about bad input. */
    static String abbreviate(String text) {
        return text.length() <= 60 ? text : text.substring(0, 60) + "…";
    }
}
