package org.habla.drivers.tekkotsu;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.habla.driver.ReadingSink;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;

/** The next line from one of Tekkotsu's line servers (Controller, emergency stop), in Latin-1 as they write it. */
final class TekkotsuLines {

    private TekkotsuLines() {
    }

    /**
     * The next line, or null when it was longer than the framer's limit (told to {@code sink} and discarded);
     * an {@link EOFException} naming {@code peer} when the server closed.
     */
    static String next(LineFramer lines, String peer, ReadingSink sink) throws IOException {
        String line;
        try {
            line = lines.readText(StandardCharsets.ISO_8859_1);
        } catch (FrameException e) {
            if (e.fatal()) {
                throw new EOFException(peer + " closed the connection");
            }
            sink.malformed(peer + " sent a line longer than maxLineBytes=" + lines.maxLineBytes() + "; discarded");
            return null;
        }
        if (line == null) {
            throw new EOFException(peer + " closed the connection");
        }
        return line;
    }
}
