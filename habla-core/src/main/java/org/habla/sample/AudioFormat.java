package org.habla.sample;

/**
 * The layout of PCM audio: signed little-endian samples, interleaved channels.
 *
 * @param sampleRateHz frames per second, e.g. 16000
 * @param channels     1 for mono, 2 for stereo
 * @param bitsPerSample 8 or 16
 */
public record AudioFormat(int sampleRateHz, int channels, int bitsPerSample) {

    public static final AudioFormat MONO_16K = new AudioFormat(16_000, 1, 16);

    public AudioFormat {
        if (sampleRateHz <= 0 || sampleRateHz > 192_000) {
            throw new IllegalArgumentException("sampleRateHz must be in 1..192000, was " + sampleRateHz);
        }
        if (channels < 1 || channels > 8) {
            throw new IllegalArgumentException("channels must be in 1..8, was " + channels);
        }
        if (bitsPerSample != 8 && bitsPerSample != 16) {
            throw new IllegalArgumentException("bitsPerSample must be 8 or 16, was " + bitsPerSample);
        }
    }

    /** Bytes in one frame (one sample of every channel). */
    public int frameBytes() {
        return channels * bitsPerSample / 8;
    }
}
