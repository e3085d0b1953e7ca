package org.habla.sim.aibo;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * Reads {@code \n}-terminated text lines of at most {@code maxBytes} from a client. A longer line is
 * consumed up to its newline and reported as {@link #TOO_LONG}, so a hostile client cannot make the
 * robot buffer without bound. Nothing is stripped: Tekkotsu's e-stop server keeps a trailing {@code \r}.
 */
final class LineInput {

    /** Returned in place of a line longer than the limit. */
    static final String TOO_LONG = "\u0000line too long";

    private final InputStream in;
    private final int maxBytes;

    LineInput(InputStream in, int maxBytes) {
        this.in = in;
        this.maxBytes = maxBytes;
    }

    /** The next line without its {@code \n}, {@link #TOO_LONG}, or null at the end of the stream. */
    String next() throws IOException {
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        boolean overflow = false;
        while (true) {
            int b = in.read();
            if (b < 0) {
                return null;
            }
            if (b == '\n') {
                return overflow ? TOO_LONG : line.toString(StandardCharsets.UTF_8);
            }
            if (line.size() < maxBytes) {
                line.write(b);
            } else {
                overflow = true;
            }
        }
    }
}
