package org.habla.drivers.pcm;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;
import org.habla.sample.AudioFormat;

/** The params of a {@code pcm-stream} interface: the layout of the raw PCM and the length of each chunk. */
public record PcmStreamParams(
        @Param(value = "Sample rate of the stream", unit = "Hz", defaultValue = "16000", min = 1_000, max = 192_000)
        int rateHz,
        @Param(value = "Interleaved channels (1 mono, 2 stereo)", defaultValue = "1", min = 1, max = 8)
        int channels,
        @Param(value = "Bits per sample: 16 (signed little-endian) or 8 (signed)", unit = "bit", defaultValue = "16")
        int bits,
        @Param(value = "Length of each audio chunk emitted", unit = "ms", defaultValue = "100",
                min = MIN_CHUNK_MS, max = MAX_CHUNK_MS)
        int chunkMs) {

    /** The shortest chunk: shorter ones cost more in per-sample overhead than they gain in latency. */
    public static final int MIN_CHUNK_MS = 5;
    /** The longest chunk. */
    public static final int MAX_CHUNK_MS = 2_000;

    public PcmStreamParams {
        if (bits != 8 && bits != 16) {
            throw new IllegalArgumentException("bits must be 8 or 16, was " + bits);
        }
    }

    /** Every parameter at its default: 16 kHz mono 16-bit, 100 ms chunks. */
    public static PcmStreamParams defaults() {
        return ParamsJson.defaults(PcmStreamParams.class);
    }

    public AudioFormat format() {
        return new AudioFormat(rateHz, channels, bits);
    }

    /** Frames in one chunk (the chunk length rounded down to whole frames). */
    public int framesPerChunk() {
        return (int) ((long) rateHz * chunkMs / 1000);
    }

    /** Bytes in one chunk. */
    public int bytesPerChunk() {
        return framesPerChunk() * format().frameBytes();
    }
}
