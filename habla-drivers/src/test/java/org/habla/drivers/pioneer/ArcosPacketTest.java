package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ArcosPacketTest {

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        "SYNC0 and PULSE,           00,          FA FB 03 00 00 00",
        "SYNC1 and OPEN,            01,          FA FB 03 01 00 01",
        "SYNC2 and CLOSE,           02,          FA FB 03 02 00 02",
        "ENABLE 1,                  04 3B 01 00, FA FB 06 04 3B 01 00 05 3B",
        "VEL +300,                  0B 3B 2C 01, FA FB 06 0B 3B 2C 01 37 3C",
        "VEL -200,                  0B 1B C8 00, FA FB 06 0B 1B C8 00 D3 1B",
        "RVEL -30,                  15 1B 1E 00, FA FB 06 15 1B 1E 00 33 1B",
        "odd length SAY,            0F 2B 02 01 06, FA FB 07 0F 2B 02 01 06 11 2A",
    })
    void everyWorkedExampleOfTheReferenceFramesByteForByte(String meaning, String data, String wire) {
        assertThat(Hex.text(ArcosPacket.of(Hex.bytes(data)).toWire())).isEqualTo(wire);
    }

    @Test
    void theChecksumOfAnOddLengthXorsTheLastByteIntoTheLowByte() {
        assertThat(ArcosPacket.checksum(Hex.bytes("0F 2B 02 01 06"), 0, 5)).isEqualTo(0x112A);
    }

    @Test
    void theChecksumKeepsOnlySixteenBits() {
        assertThat(ArcosPacket.checksum(Hex.bytes("FF FF 00 02"), 0, 4)).isEqualTo(0x0001);
    }

    @Test
    void aPacketKnowsItsTypeAndPayload() {
        ArcosPacket p = ArcosPacket.of(Hex.bytes("32 01 02"));
        assertThat(p.type()).isEqualTo(0x32);
        assertThat(p.payload()).containsExactly(1, 2);
        assertThat(p.payloadLength()).isEqualTo(2);
    }

    @Test
    void aPacketLongerThanTheCountAllowsIsRefused() {
        assertThatThrownBy(() -> ArcosPacket.of(new byte[199])).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("1..198");
        assertThat(ArcosPacket.of(new byte[198]).toWire()[2] & 0xFF).isEqualTo(200);
    }

    @Test
    void anEmptyPacketIsRefused() {
        assertThatThrownBy(() -> ArcosPacket.of()).isInstanceOf(IllegalArgumentException.class);
    }
}
