package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class EStopSessionTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final RecordingSink sink = new RecordingSink();

    @Test
    void theHandshakeAsksForTheStateAndReleasesTheStopWithBareNewlines() throws IOException {
        new EStopSession(true).handshake(InputStream.nullInputStream(), out, sink);

        assertThat(out.toString(StandardCharsets.US_ASCII)).isEqualTo("refresh\nstart\n");
    }

    @Test
    void withoutReleaseTheHandshakeOnlyAsks() throws IOException {
        new EStopSession(false).handshake(InputStream.nullInputStream(), out, sink);

        assertThat(out.toString(StandardCharsets.US_ASCII)).isEqualTo("refresh\n");
    }

    @Test
    void goodbyeEngagesTheStop() throws IOException {
        new EStopSession(true).goodbye(out);

        assertThat(out.toString(StandardCharsets.US_ASCII)).isEqualTo("stop\n");
    }

    @Test
    void theRobotsStateRepliesGoToTheStatusAndOddLinesAreCounted() throws IOException {
        EStopSession session = new EStopSession(true);
        InputStream in = new OneByteAtATime("off\non\nbogus\n".getBytes(StandardCharsets.US_ASCII));
        session.readNext(in, sink);
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.info).extracting(n -> n.get("eStop").asText()).containsExactly("off", "on");
        assertThat(sink.malformed).hasSize(1).first().asString().contains("'bogus'");
    }

    @Test
    void anOverlongLineIsDiscardedNamingTheLimitAndTheNextLineStillArrives() throws IOException {
        EStopSession session = new EStopSession(true);
        String longLine = "x".repeat(100_000) + "\noff\n";
        InputStream in = new ByteArrayInputStream(longLine.getBytes(StandardCharsets.US_ASCII));
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().hasSizeLessThan(200).contains("maxLineBytes=256");
        assertThat(sink.info).extracting(n -> n.get("eStop").asText()).containsExactly("off");
    }
}
