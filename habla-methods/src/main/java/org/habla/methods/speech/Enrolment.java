package org.habla.methods.speech;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Optional;
import java.util.ArrayList;
import java.util.List;
import org.habla.methods.audio.AudioProcessingParams;
import org.habla.methods.audio.MonoAudio;
import org.habla.methods.audio.UtteranceGate;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * A teacher's enrolment: utterances cut from their recordings or their microphone's stream by the same
 * voice-activity detector and trimming the {@code speech-recognition} method uses, and from them a
 * speaker adaptation of Sphinx's model (an MLLR transform) written to a file that the method's
 * {@code adaptation} param names.
 */
public final class Enrolment {

    /** Fewer utterances than this give too few frames for a transform worth having. */
    public static final int MIN_UTTERANCES = 3;

    private final List<AudioChunk> utterances = new ArrayList<>();

    /** The utterances taken so far (16 kHz mono 16-bit, trimmed). */
    public List<AudioChunk> utterances() {
        return List.copyOf(utterances);
    }

    /** Cuts the utterances out of a recording of any rate and channel count; returns how many it held. */
    public int addRecording(AudioChunk recording) {
        UtteranceGate gate = new UtteranceGate(recording.format().sampleRateHz(), AudioProcessingParams.defaults().gate());
        List<double[]> found = new ArrayList<>(gate.offer(MonoAudio.mix(recording)));
        // a recording may end while the teacher still speaks, or with less quiet than the hangover
        gate.offer(new double[recording.format().sampleRateHz()]).forEach(found::add);
        gate.flush().ifPresent(found::add);
        for (double[] u : found) {
            add(u, recording.format().sampleRateHz());
        }
        return found.size();
    }

    /**
     * Reads raw little-endian 16-bit PCM in {@code format} from {@code stream} (a microphone's stream)
     * until {@code count} utterances are cut from it or the stream ends; {@code onUtterance} hears of
     * each (to prompt the next phrase). Returns how many were taken.
     */
    public int addStream(InputStream stream, AudioFormat format, int count, Runnable onUtterance) throws IOException {
        UtteranceGate gate = new UtteranceGate(format.sampleRateHz(), AudioProcessingParams.defaults().gate());
        int taken = 0;
        byte[] block = new byte[format.frameBytes() * Math.max(1, format.sampleRateHz() / 50)];
        int fill = 0;
        int n;
        while (taken < count && (n = stream.read(block, fill, block.length - fill)) >= 0) {
            fill += n;
            int whole = fill - fill % format.frameBytes();
            if (whole == 0) {
                continue;
            }
            byte[] pcm = java.util.Arrays.copyOf(block, whole);
            System.arraycopy(block, whole, block, 0, fill - whole);
            fill -= whole;
            for (double[] u : gate.offer(MonoAudio.mix(AudioChunk.wrap(format, pcm)))) {
                add(u, format.sampleRateHz());
                taken++;
                onUtterance.run();
                if (taken >= count) {
                    break;
                }
            }
        }
        return taken;
    }

    private void add(double[] mono, int rateHz) {
        double[] at16k = MonoAudio.resample(mono, rateHz, 16_000);
        utterances.add(MonoAudio.chunk(UtteranceTrim.trim(at16k, 16_000), 16_000));
    }

    /**
     * What an enrolment came to: the frames of speech the adaptation rests on, the enrolment phrases
     * recognised right without it and with it, and whether the file was written.
     */
    public record Outcome(int frames, int rightBefore, int rightAfter, int phrases, boolean written) {
    }

    /**
     * Estimates the adaptation from the utterances, the teacher having said {@code phrases} in turn (the
     * list repeats when there are more utterances), with the model of {@code params}, and checks it on
     * the same utterances: the file {@code out} is written only if the adapted model recognises more of
     * them than the model as it comes, or when {@code force}d.
     */
    public Outcome write(SpeechRecognitionParams params, List<String> phrases, Path out, boolean force)
            throws IOException {
        if (utterances.size() < MIN_UTTERANCES) {
            throw new IOException("enrolment needs at least " + MIN_UTTERANCES + " utterances (MIN_UTTERANCES), got "
                    + utterances.size());
        }
        List<String> said = new ArrayList<>();
        for (int i = 0; i < utterances.size(); i++) {
            said.add(phrases.get(i % phrases.size()));
        }
        SphinxDecoder.Settings settings = SpeechRecognition.settings(params);
        Path candidate = Files.createTempFile("habla-enrol", ".mllr");
        try {
            int frames = SphinxDecoder.writeAdaptation(settings, utterances, said, candidate);
            int before = right(SphinxDecoder.load(settings, Optional.empty()), said, params.minConfidence());
            int after = right(SphinxDecoder.load(settings, Optional.of(candidate)), said, params.minConfidence());
            boolean write = force || after >= before;
            if (write) {
                Path parent = out.toAbsolutePath().getParent();
                if (parent != null) {
                    Files.createDirectories(parent);
                }
                Files.copy(candidate, out, StandardCopyOption.REPLACE_EXISTING);
            }
            return new Outcome(frames, before, after, said.size(), write);
        } finally {
            Files.deleteIfExists(candidate);
        }
    }

    private int right(SphinxDecoder decoder, List<String> said, double minConfidence) {
        int right = 0;
        for (int i = 0; i < utterances.size(); i++) {
            String expected = said.get(i);
            if (decoder.decode(utterances.get(i))
                    .filter(d -> d.confidence() >= minConfidence && d.phrase().equals(expected)).isPresent()) {
                right++;
            }
        }
        return right;
    }
}
