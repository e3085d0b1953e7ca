package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class ControllerSessionTest {

    @Test
    void eachServerIsSelectedUnderBothOfItsStoppedNamesSoItCanOnlyBeStarted() {
        List<String> commands = ControllerSession.startCommands(List.of("Walk Remote Control"), Optional.empty());

        assertThat(commands).containsExactly("!hello", "!select \"Walk Remote Control\"",
                "!select \"-Walk Remote Control\"");
    }

    @Test
    void theCameraIsSetToTcpAndItsResolutionBeforeAnyServerStarts() {
        List<String> commands = ControllerSession.startCommands(List.of("Raw Cam Server"), Optional.of(1));

        assertThat(commands).containsExactly("!hello", "!set vision.rawcam.transport=TCP",
                "!set vision.rawcam.y_skip=1", "!set vision.rawcam.uv_skip=2", "!select \"Raw Cam Server\"",
                "!select \"-Raw Cam Server\"");
    }

    @Test
    void theHandshakeWritesOneCommandALine() throws IOException {
        ControllerSession session = new ControllerSession(List.of("!hello", "!select \"X\""));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        session.handshake(InputStream.nullInputStream(), out, new RecordingSink());

        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("!hello\n!select \"X\"\n");
    }

    @Test
    void menuRefreshesAreToleratedAndHelloAndLoadGoToTheStatus() throws IOException {
        String replies = "hello\n3\nrefresh\nTekkotsuMon\n2\n0\n0\nWalk Remote Control\n0\n\n0\n1\n#World State "
                + "Serializer\n0\nsends joints\nload\norg.tekkotsu.mon.WalkGUI\nWalk Remote Control\n10050\n\"x\"\n"
                + "status\n0\nok\nhello\nmany\n";
        ControllerSession session = new ControllerSession(List.of());
        RecordingSink sink = new RecordingSink();
        InputStream in = new OneByteAtATime(replies.getBytes(StandardCharsets.UTF_8));
        for (int i = 0; i < replies.split("\n").length; i++) {
            session.readNext(in, sink);
        }

        assertThat(sink.info).hasSize(2);
        assertThat(sink.info.get(0).get("controllerHellos").asLong()).isEqualTo(3);
        assertThat(sink.info.get(1).get("lastServerStarted").asText()).isEqualTo("Walk Remote Control on port 10050");
        assertThat(sink.malformed).hasSize(1).first().asString().contains("'many'");
    }

    @Test
    void anOverlongReplyLineIsReportedNamingTheLimitAndStillTakesItsPlaceInAMessage() throws IOException {
        String replies = "load\n" + "x".repeat(5_000) + "\nWalk Remote Control\n10050\n\"x\"\nhello\n4\n";
        ControllerSession session = new ControllerSession(List.of());
        RecordingSink sink = new RecordingSink();
        InputStream in = new java.io.ByteArrayInputStream(replies.getBytes(StandardCharsets.UTF_8));
        for (int i = 0; i < 7; i++) {
            session.readNext(in, sink);
        }

        assertThat(sink.malformed).singleElement().asString().contains("maxLineBytes=4096");
        assertThat(sink.info).hasSize(2);
        assertThat(sink.info.get(0).get("lastServerStarted").asText()).isEqualTo("Walk Remote Control on port 10050");
        assertThat(sink.info.get(1).get("controllerHellos").asLong()).isEqualTo(4);
    }

    @Test
    void theControllerClosingTheConnectionEndsTheSession() {
        ControllerSession session = new ControllerSession(List.of());
        InputStream in = new java.io.ByteArrayInputStream("hello\n".getBytes(StandardCharsets.UTF_8));

        org.assertj.core.api.Assertions.assertThatThrownBy(() -> {
            for (int i = 0; i < 3; i++) {
                session.readNext(in, new RecordingSink());
            }
        }).isInstanceOf(java.io.EOFException.class).hasMessageContaining("closed the connection");
    }
}
