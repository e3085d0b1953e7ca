package org.habla.methods.speech;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/** The teacher's recorded utterances the simulator plays, read from habla-sim's sources through their index. */
public final class Utterances {

    static final Path FOLDER = Path.of("../habla-sim/src/main/resources/utterances");

    /** One recording: its path in the index, the phrase said and the audio. */
    record Utterance(String file, String phrase, AudioChunk audio) {
        String voice() {
            return file.substring(0, file.indexOf('/'));
        }
    }

    private Utterances() {
    }

    static List<Utterance> all() throws IOException {
        List<Utterance> out = new ArrayList<>();
        for (String line : Files.readAllLines(FOLDER.resolve("index.txt"), StandardCharsets.UTF_8)) {
            if (line.isBlank()) {
                continue;
            }
            String[] parts = line.split("\t");
            out.add(new Utterance(parts[0], parts[1], readWav(FOLDER.resolve(parts[0]))));
        }
        return out;
    }

    /** The PCM of a 16-bit PCM WAV file, with its format from the fmt chunk. */
    public static AudioChunk readWav(Path file) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        if (b.getInt(0) != 0x46464952 || b.getInt(8) != 0x45564157) {
            throw new IOException(file + " is not a RIFF WAVE file");
        }
        int at = 12;
        AudioFormat format = null;
        while (at + 8 <= b.limit()) {
            int id = b.getInt(at);
            int size = b.getInt(at + 4);
            if (id == 0x20746d66) { // "fmt "
                format = new AudioFormat(b.getInt(at + 12), b.getShort(at + 10), b.getShort(at + 22));
            } else if (id == 0x61746164 && format != null) { // "data"
                int n = Math.min(size, b.limit() - at - 8);
                n -= n % format.frameBytes();
                return AudioChunk.wrap(format, Arrays.copyOfRange(b.array(), at + 8, at + 8 + n));
            }
            at += 8 + size + (size & 1);
        }
        throw new IOException(file + " has no fmt and data chunks");
    }
}
