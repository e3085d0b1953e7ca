package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.io.InputStream;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * The session on the microphone server (port 10070): each packet becomes one {@code audio} chunk.
 * <pre>
 * offset 0  u16 size    bytes after the first 4 (= 4 + sample bytes; 2052 by default)
 *        2  u16 type    0 = PCM; other types are skipped by their size
 *        4  u16 rate    Hz (16000)
 *        6  u8  bits    16 (signed LE) or 8 (signed)
 *        7  u8  stereo  1 = interleaved L,R
 *        8  samples     size - 4 bytes
 * </pre>
 */
final class MicrophoneSession implements LinkSession {

    private final SessionChannel audioChannel = new SessionChannel(TekkotsuChannels.AUDIO);

    static final int PCM = 0;

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        WireInput wire = new WireInput(in);
        int size = wire.u16("microphone packet size");
        int type = wire.u16("microphone packet type");
        if (type != PCM) {
            wire.skip(size, "microphone packet of type " + type);
            sink.malformed("microphone packet of unknown type " + type + " (" + size + " bytes) skipped");
            return;
        }
        if (size < 4) {
            wire.skip(size, "short microphone packet");
            sink.malformed("microphone PCM packet of size " + size + " has no room for its 4-byte PCM header");
            return;
        }
        int rate = wire.u16("microphone sample rate");
        int bits = wire.u8("microphone bits per sample");
        int stereo = wire.u8("microphone stereo flag");
        byte[] samples = wire.bytes(size - 4, "microphone samples");
        if (rate == 0 || (bits != 8 && bits != 16) || stereo > 1) {
            sink.malformed("microphone packet with an impossible format (" + rate + " Hz, " + bits + " bits, stereo "
                    + stereo + ") skipped");
            return;
        }
        AudioFormat format = new AudioFormat(rate, stereo == 1 ? 2 : 1, bits);
        if (samples.length % format.frameBytes() != 0) {
            sink.malformed("microphone packet of " + samples.length + " sample bytes is not a whole number of "
                    + format.frameBytes() + "-byte frames; skipped");
            return;
        }
        if (samples.length > 0) {
            audioChannel.publish(sink, AudioChunk.wrap(format, samples));
        }
    }
}
