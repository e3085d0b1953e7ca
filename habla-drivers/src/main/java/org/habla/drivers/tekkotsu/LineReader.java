package org.habla.drivers.tekkotsu;

import java.io.EOFException;
import java.io.IOException;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.Optional;

/**
 * Reads {@code \n}-terminated lines of a Tekkotsu text server, at most {@link #maxBytes} a line.
 * A read time-out keeps the part of the line read so far, so a quiet server loses nothing; a longer
 * line is cut and reported through {@link Line#truncated()}.
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

    /** The next line, or empty if the server was quiet until the read time-out. */
    Optional<Line> next(InputStream in, String server) throws IOException {
        while (true) {
            int b;
            try {
                b = in.read();
            } catch (SocketTimeoutException quiet) {
                return Optional.empty();
            }
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
