package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.time.Duration;
import java.util.HexFormat;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class WalkSessionTest {

    private static final HexFormat HEX = HexFormat.ofDelimiter(" ");

    private final WalkSession session = new WalkSession(new WalkSession.WalkLimits(0.18, 0.18, 0.14, 1.8),
            Duration.ofSeconds(1));
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    @Test
    void halfSpeedForwardIsTheReferenceExampleByteForByte() throws IOException {
        session.write("walk", VectorValue.of(0.09, 0, 0), out);

        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo("66 00 00 00 3f 73 00 00 00 00 72 00 00 00 00");
    }

    @Test
    void strafeAndRotationAreFractionsOfTheirMaxima() throws IOException {
        session.write("walk", VectorValue.of(-0.045, 0.07, -0.45), out);

        // f = -0.25 (BE80 0000), s = 0.5 (3F00 0000), r = -0.25
        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo("66 00 00 80 be 73 00 00 00 3f 72 00 00 80 be");
    }

    @Test
    void speedsBeyondTheMaximaAreClampedToOne() throws IOException {
        session.write("walk", VectorValue.of(5, -5, 100), out);

        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo("66 00 00 80 3f 73 00 00 80 bf 72 00 00 80 3f");
    }

    @Test
    void keepAliveResendsTheStandingCommandUntilStopped() throws IOException {
        assertThat(session.keepAlivePeriod()).contains(Duration.ofSeconds(1));
        session.write("walk", VectorValue.of(0.09, 0, 0), out);
        byte[] command = out.toByteArray();
        out.reset();

        session.keepAlive(out);
        assertThat(out.toByteArray()).isEqualTo(command);
        out.reset();

        session.stopMotion(out);
        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo("66 00 00 00 00 73 00 00 00 00 72 00 00 00 00");
        out.reset();
        session.keepAlive(out);
        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo("66 00 00 00 00 73 00 00 00 00 72 00 00 00 00");
    }

    @Test
    void theHandshakeAndTheGoodbyeStopTheWalk() throws IOException {
        session.handshake(new ByteArrayInputStream(new byte[0]), out, new RecordingSink());
        session.goodbye(out);

        assertThat(HEX.formatHex(out.toByteArray())).isEqualTo(
                "66 00 00 00 00 73 00 00 00 00 72 00 00 00 00 66 00 00 00 00 73 00 00 00 00 72 00 00 00 00");
    }

    @Test
    void badWalkCommandsAreRejectedWithoutWritingAByte() {
        assertThatThrownBy(() -> session.write("walk", VectorValue.of(0.1, 0), out))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("[forwardMps, strafeMps, rotateRadps]");
        assertThatThrownBy(() -> session.write("walk", VectorValue.of(Double.NaN, 0, 0), out))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("finite");
        assertThatThrownBy(() -> session.write("walk", new TextValue("go"), out))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> session.write("head", VectorValue.of(0, 0, 0), out))
                .isInstanceOf(IOException.class).hasMessageContaining("only 'walk'");
        assertThat(out.size()).isZero();
    }

    @Test
    void bytesFromTheWalkServerAreCountedAndSilenceIsNotAnError() throws IOException {
        RecordingSink sink = new RecordingSink();
        session.readNext(new ByteArrayInputStream(new byte[] {1, 2, 3}), sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("3 unexpected bytes");
        assertThatThrownBy(() -> session.readNext(new ByteArrayInputStream(new byte[0]), sink))
                .isInstanceOf(IOException.class).hasMessageContaining("walk remote control closed");
    }
}
