package org.habla.drivers.lines;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;
import org.habla.sample.TextValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connection to a line stream: each line read becomes a {@code lines} reading; each {@code send}
 * command is written as one line. Overlong lines are dropped and reported; bytes that are not UTF-8 are
 * replaced with U+FFFD and reported, and the line still goes out.
 */
final class TextLinesSession implements LinkSession {

    private static final Logger LOG = LoggerFactory.getLogger(TextLinesSession.class);

    private final int maxLineBytes;
    private final LineFramer framer;
    private final byte[] readBuffer = new byte[4096];
    private final CharsetDecoder strict = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);

    TextLinesSession(TextLinesParams params) {
        this.maxLineBytes = params.maxLineBytes();
        this.framer = new LineFramer(maxLineBytes);
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        int n = in.read(readBuffer);
        if (n < 0) {
            if (framer.pending() > 0) {
                sink.malformed("the line stream ended inside a line: " + framer.pending() + " byte(s) dropped");
            }
            throw new EOFException("the line stream ended");
        }
        framer.push(readBuffer, 0, n, new LineFramer.Listener() {
            @Override
            public void line(byte[] bytes) {
                sink.reading(TextLinesDriver.LINES, new TextValue(decode(bytes, sink)));
            }

            @Override
            public void overlong(int max) {
                sink.malformed("a line longer than maxLineBytes=" + max + " was dropped");
            }
        });
    }

    private String decode(byte[] bytes, ReadingSink sink) {
        try {
            return strict.decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            sink.malformed("a line was not valid UTF-8; bad bytes replaced with U+FFFD");
            return new String(bytes, StandardCharsets.UTF_8);
        }
    }

    /**
     * Writes the text and a {@code \n}. Text holding a line end or longer than {@code maxLineBytes} is
     * refused with a warning (one command is one line); nothing is written then.
     */
    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        if (!TextLinesDriver.SEND.equals(channel)) {
            throw new IOException("the line connection carries no command channel '" + channel + "'");
        }
        if (!(command instanceof TextValue text)) {
            LOG.warn("send command {} is not text: ignored", command);
            return;
        }
        if (text.text().indexOf('\n') >= 0 || text.text().indexOf('\r') >= 0) {
            LOG.warn("send command holds a line end; one command is one line: ignored");
            return;
        }
        byte[] bytes = text.text().getBytes(StandardCharsets.UTF_8);
        if (bytes.length > maxLineBytes) {
            LOG.warn("send command of {} bytes is longer than maxLineBytes={}: ignored", bytes.length, maxLineBytes);
            return;
        }
        out.write(bytes);
        out.write('\n');
    }
}
