package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.junit.jupiter.api.Test;

class MicrophoneSessionTest {

    private final MicrophoneSession session = new MicrophoneSession();
    private final RecordingSink sink = new RecordingSink();

    /** 512 stereo frames: left = i, right = -i. */
    static byte[] stereoRamp() {
        byte[] b = new byte[2048];
        for (int i = 0; i < 512; i++) {
            short l = (short) i;
            short r = (short) -i;
            b[i * 4] = (byte) l;
            b[i * 4 + 1] = (byte) (l >> 8);
            b[i * 4 + 2] = (byte) r;
            b[i * 4 + 3] = (byte) (r >> 8);
        }
        return b;
    }

    @Test
    void aDefaultPacketIsA2052ByteBodyOf512StereoFrames() throws IOException {
        byte[] packet = TekkotsuPackets.microphone(0, 16_000, 16, 1, stereoRamp());
        assertThat(Arrays.copyOf(packet, 8)).containsExactly(0x04, 0x08, 0, 0, 0x80, 0x3E, 16, 1);

        session.readNext(new ByteArrayInputStream(packet), sink);

        AudioChunk chunk = (AudioChunk) sink.on("audio").get(0);
        assertThat(chunk.format()).isEqualTo(new AudioFormat(16_000, 2, 16));
        assertThat(chunk.frameCount()).isEqualTo(512);
        assertThat(chunk.pcm()).isEqualTo(stereoRamp());
        assertThat(chunk.channel(0)[100]).isEqualTo(100 / 32768.0);
        assertThat(chunk.channel(1)[100]).isEqualTo(-100 / 32768.0);
    }

    @Test
    void monoAndEightBitFormatsAreTakenFromTheHeader() throws IOException {
        session.readNext(new ByteArrayInputStream(TekkotsuPackets.microphone(0, 8_000, 8, 0, new byte[] {1, -2, 3})),
                sink);

        AudioChunk chunk = (AudioChunk) sink.on("audio").get(0);
        assertThat(chunk.format()).isEqualTo(new AudioFormat(8_000, 1, 8));
        assertThat(chunk.channel(0)).containsExactly(1 / 128.0, -2 / 128.0, 3 / 128.0);
    }

    @Test
    void packetsOfUnknownTypeAreSkippedByTheirSize() throws IOException {
        byte[] other = TekkotsuPackets.start().u16(6).u16(7).bytes(new byte[6]).build();
        InputStream in = new ByteArrayInputStream(WorldStateSessionTest.concat(other,
                TekkotsuPackets.microphone(0, 16_000, 16, 1, stereoRamp())));
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("unknown type 7");
        assertThat(sink.on("audio")).hasSize(1);
    }

    @Test
    void splitReadsDecodeTheSame() throws IOException {
        session.readNext(new OneByteAtATime(TekkotsuPackets.microphone(0, 16_000, 16, 1, stereoRamp())), sink);

        assertThat(((AudioChunk) sink.on("audio").get(0)).pcm()).isEqualTo(stereoRamp());
    }

    @Test
    void impossibleFormatsAndPartialFramesAreReportedAndTheStreamGoesOn() throws IOException {
        InputStream in = new ByteArrayInputStream(WorldStateSessionTest.concat(
                TekkotsuPackets.microphone(0, 16_000, 12, 1, new byte[4]),
                TekkotsuPackets.microphone(0, 16_000, 16, 1, new byte[6]),
                TekkotsuPackets.start().u16(2).u16(0).u16(0).build(),
                TekkotsuPackets.microphone(0, 16_000, 16, 1, new byte[8])));
        for (int i = 0; i < 4; i++) {
            session.readNext(in, sink);
        }

        assertThat(sink.malformed).hasSize(3);
        assertThat(sink.malformed.get(0)).contains("impossible format");
        assertThat(sink.malformed.get(1)).contains("not a whole number");
        assertThat(sink.malformed.get(2)).contains("size 2");
        assertThat(sink.on("audio")).hasSize(1);
    }

    @Test
    void aPacketCutShortEndsTheLink() {
        byte[] packet = TekkotsuPackets.microphone(0, 16_000, 16, 1, stereoRamp());

        assertThatThrownBy(() -> session.readNext(new ByteArrayInputStream(Arrays.copyOf(packet, 1000)), sink))
                .isInstanceOf(EOFException.class).hasMessageContaining("microphone samples");
    }
}
