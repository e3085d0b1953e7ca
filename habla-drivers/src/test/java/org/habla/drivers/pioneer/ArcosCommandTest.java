package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class ArcosCommandTest {

    private static String wire(ArcosPacket p) {
        return Hex.text(p.toWire());
    }

    @Test
    void theHandshakeAndSessionCommandsAreTheCommandByteAlone() {
        assertThat(wire(ArcosCommand.SYNC0.packet())).isEqualTo("FA FB 03 00 00 00");
        assertThat(wire(ArcosCommand.SYNC1.packet())).isEqualTo("FA FB 03 01 00 01");
        assertThat(wire(ArcosCommand.SYNC2.packet())).isEqualTo("FA FB 03 02 00 02");
        assertThat(wire(ArcosCommand.PULSE.packet())).isEqualTo("FA FB 03 00 00 00");
        assertThat(wire(ArcosCommand.OPEN.packet())).isEqualTo("FA FB 03 01 00 01");
        assertThat(wire(ArcosCommand.CLOSE.packet())).isEqualTo("FA FB 03 02 00 02");
    }

    @Test
    void stopAndEmergencyStopAreCommandTwentyNineAndFiftyFive() {
        assertThat(wire(ArcosCommand.STOP.packet())).isEqualTo("FA FB 03 1D 00 1D");
        assertThat(wire(ArcosCommand.E_STOP.packet())).isEqualTo("FA FB 03 37 00 37");
    }

    @Test
    void enableTakesAPositiveIntegerArgument() {
        assertThat(wire(ArcosCommand.ENABLE.packet(1))).isEqualTo("FA FB 06 04 3B 01 00 05 3B");
        assertThat(wire(ArcosCommand.ENABLE.packet(0))).isEqualTo("FA FB 06 04 3B 00 00 04 3B");
    }

    @Test
    void sonarOnAndOffAreCommandTwentyEight() {
        assertThat(wire(ArcosCommand.SONAR.packet(1))).isEqualTo("FA FB 06 1C 3B 01 00 1D 3B");
        assertThat(wire(ArcosCommand.SONAR.packet(0))).isEqualTo("FA FB 06 1C 3B 00 00 1C 3B");
    }

    @Test
    void aNegativeArgumentTravelsAsItsMagnitudeWithTheNegativeType() {
        assertThat(wire(ArcosCommand.VEL.packet(300))).isEqualTo("FA FB 06 0B 3B 2C 01 37 3C");
        assertThat(wire(ArcosCommand.VEL.packet(-200))).isEqualTo("FA FB 06 0B 1B C8 00 D3 1B");
        assertThat(wire(ArcosCommand.RVEL.packet(-30))).isEqualTo("FA FB 06 15 1B 1E 00 33 1B");
        assertThat(wire(ArcosCommand.RVEL.packet(45))).isEqualTo("FA FB 06 15 3B 2D 00 42 3B");
    }

    @Test
    void anArgumentBeyondTwoBytesIsRefused() {
        assertThat(wire(ArcosCommand.VEL.packet(-65535))).isEqualTo("FA FB 06 0B 1B FF FF 0B 1A");
        assertThatThrownBy(() -> ArcosCommand.VEL.packet(65536)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("VEL");
    }
}
