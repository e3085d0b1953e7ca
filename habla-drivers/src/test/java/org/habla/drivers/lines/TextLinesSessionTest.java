package org.habla.drivers.lines;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.habla.drivers.pcm.LoopbackPeer;
import org.habla.drivers.pioneer.RecordingSink;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class TextLinesSessionTest {

    private final RecordingSink sink = new RecordingSink();

    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private void readUntil(TextLinesSession session, LoopbackPeer peer, int lines) throws IOException {
        for (int i = 0; i < 100 && sink.on("lines").size() < lines; i++) {
            session.readNext(peer.driverIn(), sink);
        }
    }

    @Test
    void typedRewardsArriveAsLinesOfText() throws Exception {
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(utf8("1\r\n-1\n0.5\n"), 2);
            TextLinesSession session = new TextLinesSession(TextLinesParams.defaults());
            readUntil(session, peer, 3);
        }
        assertThat(sink.on("lines")).containsExactly(new TextValue("1"), new TextValue("-1"), new TextValue("0.5"));
        assertThat(sink.malformed()).isEmpty();
    }

    @Test
    void anOverlongLineIsCountedAsMalformedAndTheNextLineStillArrives() throws Exception {
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(utf8("y".repeat(5_000) + "\nstill here\n"), 1_000);
            TextLinesSession session = new TextLinesSession(TextLinesParams.defaults());
            readUntil(session, peer, 1);
        }
        assertThat(sink.on("lines")).containsExactly(new TextValue("still here"));
        assertThat(sink.malformed()).singleElement().asString().contains("maxLineBytes=1024");
    }

    @Test
    void invalidUtf8IsReplacedAndCounted() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        bytes.writeBytes(utf8("caf"));
        bytes.write(0xE9);
        bytes.writeBytes(utf8("\nniño\n"));
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(bytes.toByteArray(), bytes.size());
            TextLinesSession session = new TextLinesSession(TextLinesParams.defaults());
            readUntil(session, peer, 2);
        }
        assertThat(sink.on("lines")).containsExactly(new TextValue("caf\uFFFD"), new TextValue("niño"));
        assertThat(sink.malformed()).singleElement().asString().contains("UTF-8");
    }

    @Test
    void thePeerHangingUpMidLineEndsTheSessionAndReportsTheFragment() throws Exception {
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(utf8("done\nhalf"), 100);
            peer.deviceHangsUp();
            TextLinesSession session = new TextLinesSession(TextLinesParams.defaults());
            assertThatThrownBy(() -> {
                for (int i = 0; i < 10; i++) {
                    session.readNext(peer.driverIn(), sink);
                }
            }).isInstanceOf(EOFException.class);
        }
        assertThat(sink.on("lines")).containsExactly(new TextValue("done"));
        assertThat(sink.malformed()).singleElement().asString().contains("4 byte(s)");
    }

    @Test
    void sendWritesTheTextAsOneLine() throws Exception {
        try (LoopbackPeer peer = new LoopbackPeer()) {
            TextLinesSession session = new TextLinesSession(TextLinesParams.defaults());
            session.write("send", new TextValue("reward noted: ñ"), peer.driverOut());
            peer.driverOut().flush();
            assertThat(new String(peer.deviceReads(utf8("reward noted: ñ\n").length), StandardCharsets.UTF_8))
                    .isEqualTo("reward noted: ñ\n");
        }
    }

    @Test
    void sendRefusesTextThatIsNotOneLineOrTooLongAndWritesNothing() throws IOException {
        TextLinesSession session = new TextLinesSession(new TextLinesParams(10));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Payload bad : java.util.List.of(new TextValue("two\nlines"), new TextValue("cr\r"),
                new TextValue("eleven byte"), new NumberValue(1))) {
            session.write("send", bad, out);
        }
        assertThat(out.size()).isZero();
        session.write("send", new TextValue("ten bytes!"), out);
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("ten bytes!\n");
    }

    @Test
    void aCommandOnAnotherChannelIsAnError() {
        assertThatThrownBy(() -> new TextLinesSession(TextLinesParams.defaults())
                .write("motion", new TextValue("x"), new ByteArrayOutputStream()))
                .isInstanceOf(IOException.class).hasMessageContaining("motion");
    }
}
