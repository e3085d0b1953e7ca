package org.habla.methods.notes;

import java.util.Set;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.audio.MonoAudio;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * Hears musical notes, type {@code note-recognition}: the Pioneer's teacher gives commands by
 * playing notes. Input {@code audio} takes a stream (or the segments of {@code audio-processing}),
 * any rate, mixed to mono; overlapping frames go through a spectral tone detector (strongest peak,
 * its distance above the noise, its distance from the nearest note) and a tracker that reports a
 * note once it has sounded for {@code minDurationMs}. Output {@code note} carries the note's name,
 * e.g. {@code C5}, once per note event.
 */
public final class NoteRecognition extends ProcessingMethod {

    private static final OutputPort<TextValue> NOTE = OutputPort.of("note", TextValue.class,
            Shape.text("name of a note heard, e.g. C5, once per note event"));

    private final NoteRecognitionParams params;
    private final Set<Note> allowed;
    private final Output<TextValue> note = output(NOTE);

    private AudioFormat format;
    private ToneDetector detector;
    private NoteTracker tracker;
    private double[] window = new double[0];
    private int filled;
    private int hop;

    NoteRecognition(NoteRecognitionParams params) {
        this.params = params;
        this.allowed = params.allowedNotes();
        input(audio(params), this::onAudio);
    }

    /** The ports of a note recognition whose input queue holds {@code queue} chunks. */
    static Ports ports(NoteRecognitionParams params) {
        return Ports.of(audio(params), NOTE);
    }

    private static InputPort<AudioChunk> audio(NoteRecognitionParams params) {
        return InputPort.of("audio", AudioChunk.class, Delivery.queue(params.queue()));
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        if (!chunk.format().equals(format)) {
            restart(chunk.format());
        }
        double[] mono = MonoAudio.mix(chunk);
        int at = 0;
        while (at < mono.length) {
            int take = Math.min(window.length - filled, mono.length - at);
            System.arraycopy(mono, at, window, filled, take);
            filled += take;
            at += take;
            if (filled == window.length) {
                tracker.next(detector.detect(window)).ifPresent(n -> emit(note, new TextValue(n.name())));
                System.arraycopy(window, hop, window, 0, window.length - hop);
                filled -= hop;
            }
        }
    }

    private void restart(AudioFormat next) {
        format = next;
        int rate = next.sampleRateHz();
        int frame = Math.max(16, (int) Math.round(params.frameMs() * rate / 1000));
        hop = Math.max(1, Math.min(frame, (int) Math.round(params.hopMs() * rate / 1000)));
        window = new double[frame];
        filled = 0;
        detector = new ToneDetector(rate, frame, params, allowed);
        tracker = new NoteTracker(1000.0 * hop / rate, 1000.0 * frame / rate, params.minDurationMs(),
                params.maxDropoutMs());
    }

    /** Makes {@code note-recognition} methods. */
    public static final class Provider extends SimpleMethodProvider<NoteRecognitionParams> {
        public Provider() {
            super("note-recognition", "Names the musical notes heard in audio, once per note",
                    NoteRecognitionParams.class, NoteRecognition::ports, (layer, p) -> new NoteRecognition(p),
                    Layer.PROCESSING);
        }
    }
}
