package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.HexFormat;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.NumberValue;
import org.junit.jupiter.api.Test;

class SpeakerSessionTest {

    private final SpeakerSession session = new SpeakerSession(16_000);

    @Test
    void monoSixteenBitAtTheServerRateIsSentAsIsByteForByte() throws IOException {
        byte[] pcm = {0x01, 0x02, (byte) 0xff, 0x7f};
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        session.write("speaker", AudioChunk.of(AudioFormat.MONO_16K, pcm), out);

        // size 8 = 4 + 4 sample bytes, type 0, rate 16000, 16 bits, padding, samples
        assertThat(HexFormat.ofDelimiter(" ").formatHex(out.toByteArray()))
                .isEqualTo("08 00 00 00 80 3e 10 00 01 02 ff 7f");
    }

    @Test
    void stereoIsAveragedToMono() {
        byte[] pcm = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN)
                .putShort((short) 1000).putShort((short) 3000).putShort((short) -200).putShort((short) 0).array();
        short[] mono = samples(session.encode(AudioChunk.of(new AudioFormat(16_000, 2, 16), pcm)));

        assertThat(mono).containsExactly((short) 2000, (short) -100);
    }

    @Test
    void eightBitSignedIsWidened() {
        short[] mono = samples(session.encode(AudioChunk.of(new AudioFormat(16_000, 1, 8), new byte[] {64, -128})));

        assertThat(mono).containsExactly((short) 16384, (short) -32768);
    }

    @Test
    void otherRatesAreResampledToTheServerRate() {
        byte[] pcm = ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN)
                .putShort((short) 0).putShort((short) 1000).putShort((short) 2000).putShort((short) 3000).array();
        byte[] packet = session.encode(AudioChunk.of(new AudioFormat(8_000, 1, 16), pcm));
        short[] mono = samples(packet);

        assertThat(mono).hasSize(8);
        assertThat(mono).startsWith((short) 0, (short) 500, (short) 1000, (short) 1500, (short) 2000);
        assertThat(ByteBuffer.wrap(packet).order(ByteOrder.LITTLE_ENDIAN).getShort(4)).isEqualTo((short) 16_000);
    }

    @Test
    void aLongChunkIsCutIntoPacketsTheServerAccepts() {
        byte[] pcm = new byte[100_000];
        byte[] packets = session.encode(AudioChunk.of(AudioFormat.MONO_16K, pcm));
        ByteBuffer b = ByteBuffer.wrap(packets).order(ByteOrder.LITTLE_ENDIAN);

        int first = b.getShort(0) & 0xffff;
        assertThat(first).isEqualTo(4 + SpeakerSession.MAX_SAMPLE_BYTES);
        int second = b.getShort(4 + first) & 0xffff;
        assertThat(second).isEqualTo(4 + 100_000 - SpeakerSession.MAX_SAMPLE_BYTES);
        assertThat(packets).hasSize(8 + 8 + 100_000);
    }

    @Test
    void somethingThatIsNotAudioIsRejectedWithoutWriting() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();

        assertThatThrownBy(() -> session.write("speaker", new NumberValue(1), out))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("speaker takes audio");
        assertThat(out.size()).isZero();
        assertThat(session.encode(AudioChunk.of(AudioFormat.MONO_16K, new byte[0]))).isEmpty();
    }

    /** The samples of a single packet. */
    static short[] samples(byte[] packet) {
        ByteBuffer b = ByteBuffer.wrap(packet).order(ByteOrder.LITTLE_ENDIAN);
        int size = b.getShort(0) & 0xffff;
        assertThat(b.getShort(2)).isZero();
        assertThat(b.get(6)).isEqualTo((byte) 16);
        assertThat(packet).hasSize(4 + size);
        short[] s = new short[(size - 4) / 2];
        for (int i = 0; i < s.length; i++) {
            s[i] = b.getShort(8 + 2 * i);
        }
        return s;
    }
}
