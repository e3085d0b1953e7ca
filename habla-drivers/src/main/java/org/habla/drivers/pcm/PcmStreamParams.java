package org.habla.drivers.pcm;

import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.sample.AudioFormat;

/** The params of a {@code pcm-stream} interface: the layout of the raw PCM and the length of each chunk. */
public record PcmStreamParams(
        @Param(value = "Sample rate of the stream", unit = "Hz", defaultValue = "16000")
        Integer rateHz,
        @Param(value = "Interleaved channels (1 mono, 2 stereo)", defaultValue = "1")
        Integer channels,
        @Param(value = "Bits per sample: 16 (signed little-endian) or 8 (signed)", unit = "bit", defaultValue = "16")
        Integer bits,
        @Param(value = "Length of each audio chunk emitted", unit = "ms", defaultValue = "100")
        Integer chunkMs) {

    /** The shortest chunk: shorter ones cost more in per-sample overhead than they gain in latency. */
    public static final int MIN_CHUNK_MS = 5;
    /** The longest chunk. */
    public static final int MAX_CHUNK_MS = 2_000;

    public PcmStreamParams {
        rateHz = ParamDefaults.or(PcmStreamParams.class, "rateHz", rateHz);
        channels = ParamDefaults.or(PcmStreamParams.class, "channels", channels);
        bits = ParamDefaults.or(PcmStreamParams.class, "bits", bits);
        chunkMs = ParamDefaults.or(PcmStreamParams.class, "chunkMs", chunkMs);
        if (rateHz < 1_000 || rateHz > 192_000) {
            throw new IllegalArgumentException("rateHz must be in 1000..192000, was " + rateHz);
        }
        if (channels < 1 || channels > 8) {
            throw new IllegalArgumentException("channels must be in 1..8, was " + channels);
        }
        if (bits != 8 && bits != 16) {
            throw new IllegalArgumentException("bits must be 8 or 16, was " + bits);
        }
        if (chunkMs < MIN_CHUNK_MS || chunkMs > MAX_CHUNK_MS) {
            throw new IllegalArgumentException("chunkMs must be in " + MIN_CHUNK_MS + ".." + MAX_CHUNK_MS + ", was " + chunkMs);
        }
    }

    /** Every parameter at its default: 16 kHz mono 16-bit, 100 ms chunks. */
    public static PcmStreamParams defaults() {
        return new PcmStreamParams(null, null, null, null);
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
