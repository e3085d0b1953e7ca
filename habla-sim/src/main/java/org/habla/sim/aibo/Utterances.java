package org.habla.sim.aibo;

import java.io.BufferedInputStream;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.UnsupportedAudioFileException;

/**
 * The teacher's recorded phrases, shipped in {@code habla-sim/src/main/resources/utterances/}: 16 kHz mono
 * 16-bit WAV takes in several voices, listed in {@code index.txt} as {@code <voice>/<file>\t<phrase>}.
 * {@link #take} picks one take of a phrase at random, so the robot never hears exactly the same sound twice
 * in a row.
 */
public final class Utterances {

    private static final String ROOT = "/utterances/";

    private final Map<String, List<String>> takes;
    private final SplittableRandom random;

    private Utterances(Map<String, List<String>> takes, long seed) {
        this.takes = takes;
        this.random = new SplittableRandom(seed);
    }

    /** The takes shipped with HABLA. */
    public static Utterances shipped(long seed) {
        try (InputStream in = Utterances.class.getResourceAsStream(ROOT + "index.txt")) {
            if (in == null) {
                throw new IllegalStateException("the utterances index " + ROOT + "index.txt is missing");
            }
            Map<String, List<String>> takes = new HashMap<>();
            BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                String[] parts = line.split("\t");
                if (parts.length == 2) {
                    takes.computeIfAbsent(parts[1].strip(), k -> new ArrayList<>()).add(parts[0].strip());
                }
            }
            return new Utterances(Map.copyOf(takes), seed);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Whether some take says {@code phrase}. */
    public boolean has(String phrase) {
        return takes.containsKey(phrase);
    }

    /** One take of {@code phrase} as 16 kHz mono samples. */
    public synchronized short[] take(String phrase) {
        List<String> files = takes.get(phrase);
        if (files == null) {
            throw new IllegalArgumentException("no recorded take says '" + phrase + "' (phrases: "
                    + takes.keySet().stream().sorted().toList() + ")");
        }
        String file = files.get(random.nextInt(files.size()));
        try (InputStream raw = Utterances.class.getResourceAsStream(ROOT + file)) {
            if (raw == null) {
                throw new IllegalStateException("the utterance " + ROOT + file + " listed in the index is missing");
            }
            return samples(new BufferedInputStream(raw), file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The samples of a 16 kHz mono 16-bit WAV stream. */
    static short[] samples(InputStream wav, String name) throws IOException {
        try (AudioInputStream audio = AudioSystem.getAudioInputStream(wav)) {
            AudioFormat f = audio.getFormat();
            if (f.getSampleRate() != Microphone.RATE_HZ || f.getChannels() != 1 || f.getSampleSizeInBits() != 16
                    || f.getEncoding() != AudioFormat.Encoding.PCM_SIGNED || f.isBigEndian()) {
                throw new IOException(name + " is " + f + ", not 16 kHz mono 16-bit signed little-endian PCM");
            }
            byte[] bytes = audio.readAllBytes();
            short[] out = new short[bytes.length / 2];
            ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).asShortBuffer().get(out);
            return out;
        } catch (UnsupportedAudioFileException e) {
            throw new IOException(name + " is not a WAV file: " + e.getMessage(), e);
        }
    }
}
