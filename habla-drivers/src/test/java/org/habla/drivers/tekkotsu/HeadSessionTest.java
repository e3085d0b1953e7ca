package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class HeadSessionTest {

    @Test
    void anglesAtTheLimitsAreSentAsMinusOneAndOne() {
        byte[] b = HeadSession.encode(VectorValue.of(Math.toRadians(-75), Math.toRadians(88), Math.toRadians(-15)));

        assertThat(letters(b)).isEqualTo("tpr");
        assertThat(values(b)).containsExactly(-1f, 1f, -1f);
    }

    @Test
    void anAngleIsAFractionOfTheLimitOnItsOwnSide() {
        byte[] b = HeadSession.encode(VectorValue.of(Math.toRadians(-30), Math.toRadians(-44), Math.toRadians(22.5)));

        float[] v = values(b);
        assertThat(v[0]).isCloseTo(-0.4f, within(1e-6f));
        assertThat(v[1]).isCloseTo(-0.5f, within(1e-6f));
        assertThat(v[2]).isCloseTo(0.5f, within(1e-6f));
    }

    @Test
    void tiltUpwardsIsZeroBecauseTheErs7TiltMaximumIsZeroAndBeyondTheLimitsIsClamped() {
        byte[] b = HeadSession.encode(VectorValue.of(0.3, Math.toRadians(200), Math.toRadians(-90)));

        assertThat(values(b)).containsExactly(0f, 1f, -1f);
    }

    @Test
    void theRobotsMappingOfTheSentValueGivesBackTheAngle() {
        double min = Math.toRadians(-15);
        double max = Math.toRadians(45);
        for (double angle : new double[] {-0.2, -0.05, 0, 0.1, 0.7}) {
            double v = HeadSession.fraction(angle, min, max);
            double robot = Math.abs(v) * (v > 0 ? max : min);
            assertThat(robot).isCloseTo(angle, within(1e-12));
        }
    }

    @Test
    void aCommandThatIsNotThreeFiniteAnglesIsRejectedWithoutWriting() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        HeadSession session = new HeadSession();

        assertThatThrownBy(() -> session.write("head", VectorValue.of(0, 0), out))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("[tiltRad, panRad, nodRad]");
        assertThatThrownBy(() -> session.write("head", VectorValue.of(0, Double.POSITIVE_INFINITY, 0), out))
                .isInstanceOf(IllegalArgumentException.class);
        assertThat(out.size()).isZero();
    }

    @Test
    void theSessionWritesFifteenBytes() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        new HeadSession().write("head", VectorValue.of(0, 0, 0), out);

        assertThat(out.toByteArray()).containsExactly('t', 0, 0, 0, 0, 'p', 0, 0, 0, 0, 'r', 0, 0, 0, 0);
    }

    static String letters(byte[] b) {
        return "" + (char) b[0] + (char) b[5] + (char) b[10];
    }

    static float[] values(byte[] b) {
        ByteBuffer buf = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        return new float[] {buf.getFloat(1), buf.getFloat(6), buf.getFloat(11)};
    }
}
