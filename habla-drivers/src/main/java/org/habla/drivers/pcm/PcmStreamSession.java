package org.habla.drivers.pcm;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * One connection to a raw PCM stream: bytes are gathered until a chunk of {@code chunkMs} is whole, then
 * emitted on {@code audio}. The stream has no framing, so every chunk is a whole number of frames by
 * construction; a partial chunk left when the stream ends is emitted as its whole frames (a trailing
 * partial frame cannot be played and is dropped with a report).
 */
final class PcmStreamSession implements LinkSession {

    private final SessionChannel audioChannel = new SessionChannel(PcmStreamDriver.AUDIO);

    private final AudioFormat format;
    private final byte[] chunk;
    private final long chunkMicros;
    private int filled;

    PcmStreamSession(PcmStreamParams params) {
        this.format = params.format();
        this.chunk = new byte[params.bytesPerChunk()];
        this.chunkMicros = params.framesPerChunk() * 1_000_000L / params.rateHz();
    }

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        while (filled < chunk.length) {
            int n = in.read(chunk, filled, chunk.length - filled);
            if (n < 0) {
                endOfStream(sink);
            }
            filled += n;
        }
        // the chunk's source time is when its first frame was captured: one chunk before it completed
        long nowMicros = System.currentTimeMillis() * 1_000L;
        audioChannel.publish(sink, AudioChunk.wrap(format, chunk.clone()), nowMicros - chunkMicros);
        filled = 0;
    }

    private void endOfStream(ReadingSink sink) throws EOFException {
        int frameBytes = format.frameBytes();
        int whole = filled - filled % frameBytes;
        if (whole > 0) {
            long frames = whole / frameBytes;
            long nowMicros = System.currentTimeMillis() * 1_000L;
            audioChannel.publish(sink, AudioChunk.wrap(format, Arrays.copyOf(chunk, whole)),
                    nowMicros - frames * 1_000_000L / format.sampleRateHz());
        }
        if (filled % frameBytes != 0) {
            sink.malformed("PCM stream ended inside a frame: " + (filled % frameBytes) + " byte(s) dropped");
        }
        filled = 0;
        throw new EOFException("the PCM stream ended");
    }
}
