package org.habla.sim.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.util.HexFormat;
import org.junit.jupiter.api.Test;

class ArcosFramesTest {

    private static final HexFormat HEX = HexFormat.ofDelimiter(" ").withUpperCase();

    @Test
    void framesMatchTheReferencesWorkedExamples() {
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("00")))).isEqualTo("FA FB 03 00 00 00");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("02")))).isEqualTo("FA FB 03 02 00 02");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("04 3B 01 00")))).isEqualTo("FA FB 06 04 3B 01 00 05 3B");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("0B 3B 2C 01")))).isEqualTo("FA FB 06 0B 3B 2C 01 37 3C");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("0B 1B C8 00")))).isEqualTo("FA FB 06 0B 1B C8 00 D3 1B");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("15 1B 1E 00")))).isEqualTo("FA FB 06 15 1B 1E 00 33 1B");
        assertThat(HEX.formatHex(ArcosFrames.frame(bytes("0F 2B 02 01 06")))).isEqualTo("FA FB 07 0F 2B 02 01 06 11 2A");
    }

    @Test
    void theReaderFindsPacketsAmongGarbageAndDropsBadChecksums() throws IOException {
        ByteArrayOutputStream s = new ByteArrayOutputStream();
        s.writeBytes(bytes("13 FA 00 FB FA FA"));
        s.writeBytes(ArcosFrames.frame(bytes("0B 3B 2C 01")));
        byte[] corrupt = ArcosFrames.frame(bytes("15 1B 1E 00"));
        corrupt[5] ^= 0x01;
        s.writeBytes(corrupt);
        s.writeBytes(bytes("FA FB 01"));
        s.writeBytes(ArcosFrames.frame(bytes("1D")));
        ArcosFrames frames = new ArcosFrames(new ByteArrayInputStream(s.toByteArray()));
        assertThat(HEX.formatHex(frames.next())).isEqualTo("0B 3B 2C 01");
        assertThat(HEX.formatHex(frames.next())).isEqualTo("1D");
        assertThat(frames.dropped()).isEqualTo(2);
        assertThatThrownBy(frames::next).isInstanceOf(EOFException.class);
    }

    @Test
    void aClientThatLeavesInsideAPacketEndsTheStreamCleanly() {
        ArcosFrames frames = new ArcosFrames(new ByteArrayInputStream(bytes("FA FB 06 0B 3B")));
        assertThatThrownBy(frames::next).isInstanceOf(EOFException.class).hasMessageContaining("inside a packet");
    }

    @Test
    void integerArgumentsCarryTheirSignInTheTypeByte() {
        assertThat(ArcosArgs.intArg(bytes("0B 3B 2C 01"))).hasValue(300);
        assertThat(ArcosArgs.intArg(bytes("0B 1B C8 00"))).hasValue(-200);
        assertThat(ArcosArgs.intArg(bytes("0B"))).isEmpty();
        assertThat(ArcosArgs.intArg(bytes("0B 2B 01 41"))).isEmpty();
    }

    private static byte[] bytes(String hex) {
        return HexFormat.ofDelimiter(" ").parseHex(hex);
    }
}
