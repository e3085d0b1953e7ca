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
import org.habla.driver.SessionChannel;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;
import org.habla.sample.Payload;
import org.habla.sample.TextValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connection to a line stream: each line read becomes a {@code lines} reading; each {@code send}
 * command is written as one line. Lines are cut by HABLA's {@link LineFramer}: at {@code \n}, a {@code \r}
 * before it removed. Overlong lines are dropped and reported; bytes that are not UTF-8 are replaced with
 * U+FFFD and reported, and the line still goes out.
 */
final class TextLinesSession implements LinkSession {

    private final SessionChannel linesChannel = new SessionChannel(TextLinesDriver.LINES);

    private static final Logger LOG = LoggerFactory.getLogger(TextLinesSession.class);

    private final int maxLineBytes;
    /** Made on the first read, over the connection's stream, which it then reads ahead of. */
    private LineFramer framer;
    private final CharsetDecoder strict = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);

    TextLinesSession(TextLinesParams params) {
        this.maxLineBytes = params.maxLineBytes();
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        if (framer == null) {
            framer = new LineFramer(in, maxLineBytes);
        }
        byte[] line;
        try {
            line = framer.readLine();
        } catch (FrameException e) {
            if (e.code().equals("line_too_long")) {
                sink.malformed("a line longer than maxLineBytes=" + maxLineBytes + " was dropped");
            } else {
                sink.malformed("the line connection: " + e.getMessage());
            }
            if (e.fatal()) {
                throw new EOFException("the line stream ended");
            }
            return;
        }
        if (line == null) {
            throw new EOFException("the line stream ended");
        }
        linesChannel.publish(sink, new TextValue(decode(line, sink)));
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
