package org.habla.sample;

import java.util.Arrays;
import java.util.Objects;

/** A run of PCM audio in a stated format. */
public final class AudioChunk implements Payload {

    private final AudioFormat format;
    private final byte[] pcm;

    private AudioChunk(AudioFormat format, byte[] pcm) {
        this.format = Objects.requireNonNull(format, "format");
        if (pcm.length % format.frameBytes() != 0) {
            throw new IllegalArgumentException("audio of " + pcm.length + " bytes is not a whole number of "
                    + format.frameBytes() + "-byte frames");
        }
        this.pcm = pcm;
    }

    public static AudioChunk of(AudioFormat format, byte[] pcm) {
        return new AudioChunk(format, pcm.clone());
    }

    /** Takes ownership of {@code pcm}; the caller must not touch the array again. */
    public static AudioChunk wrap(AudioFormat format, byte[] pcm) {
        return new AudioChunk(format, pcm);
    }

    public AudioFormat format() {
        return format;
    }

    /** A copy of the PCM bytes. */
    public byte[] pcm() {
        return pcm.clone();
    }

    public int byteCount() {
        return pcm.length;
    }

    public int frameCount() {
        return pcm.length / format.frameBytes();
    }

    /**
     * The samples of one channel as numbers in [-1, 1).
     */
    public double[] channel(int channel) {
        if (channel < 0 || channel >= format.channels()) {
            throw new IllegalArgumentException("no channel " + channel + " in " + format);
        }
        int frames = frameCount();
        double[] out = new double[frames];
        int stride = format.frameBytes();
        if (format.bitsPerSample() == 16) {
            for (int i = 0; i < frames; i++) {
                int at = i * stride + channel * 2;
                short s = (short) ((pcm[at] & 0xff) | (pcm[at + 1] << 8));
                out[i] = s / 32768.0;
            }
        } else {
            for (int i = 0; i < frames; i++) {
                out[i] = pcm[i * stride + channel] / 128.0;
            }
        }
        return out;
    }

    /** Writes the bytes to {@code out} without copying them first. */
    public void writeTo(java.io.OutputStream out) throws java.io.IOException {
        out.write(pcm);
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.AUDIO;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AudioChunk a && format.equals(a.format) && Arrays.equals(pcm, a.pcm);
    }

    @Override
    public int hashCode() {
        return 31 * format.hashCode() + Arrays.hashCode(pcm);
    }

    @Override
    public String toString() {
        return "AudioChunk[" + format + ", " + pcm.length + " bytes]";
    }
}
