package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.habla.sample.AudioChunk;
import org.habla.sample.Payload;

/**
 * The session on the speaker server (port 10071): a {@code speaker} chunk is converted to what the
 * server plays — mono, 16-bit signed little-endian, at {@code speakerRateHz} (channels averaged,
 * other rates resampled linearly) — and sent as packets of at most {@link #MAX_SAMPLE_BYTES}.
 * <pre>
 * offset 0  u16 size   bytes after this 4-byte header (= 4 + sample bytes)
 *        2  u16 type   0 = PCM
 *        4  u16 rate   Hz
 *        6  u8  bits   16
 *        7  u8  0      padding
 *        8  samples    size - 4 bytes, mono
 * </pre>
 */
final class SpeakerSession extends CommandOnlySession {

    /** Tekkotsu's own client sends at most this many sample bytes a packet. */
    static final int MAX_SAMPLE_BYTES = 65_530;

    private final int rateHz;

    SpeakerSession(int rateHz) {
        super("speaker server");
        this.rateHz = rateHz;
    }

    @Override
    public void write(String channel, Payload command, OutputStream out) throws IOException {
        if (!TekkotsuChannels.SPEAKER.equals(channel)) {
            throw new IOException("the speaker connection carries only '" + TekkotsuChannels.SPEAKER + "', not '"
                    + channel + "'");
        }
        if (!(command instanceof AudioChunk chunk)) {
            throw new IllegalArgumentException("speaker takes audio, got " + command);
        }
        out.write(encode(chunk));
    }

    /** The packets for one chunk, back to back; nothing for an empty chunk. */
    byte[] encode(AudioChunk chunk) {
        short[] mono = SpeakerPcm.toMono16(chunk, rateHz);
        int perPacket = MAX_SAMPLE_BYTES / 2;
        int packets = (mono.length + perPacket - 1) / perPacket;
        ByteBuffer b = ByteBuffer.allocate(mono.length * 2 + packets * 8).order(ByteOrder.LITTLE_ENDIAN);
        for (int start = 0; start < mono.length; start += perPacket) {
            int n = Math.min(perPacket, mono.length - start);
            b.putShort((short) (4 + n * 2)).putShort((short) 0);
            b.putShort((short) rateHz).put((byte) 16).put((byte) 0);
            for (int i = 0; i < n; i++) {
                b.putShort(mono[start + i]);
            }
        }
        return b.array();
    }
}
