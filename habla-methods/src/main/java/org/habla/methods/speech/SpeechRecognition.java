// Over 300 lines, on purpose: the method's inputs, its model loading, queue and decoding are one life cycle.
package org.habla.methods.speech;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.audio.MonoAudio;
import org.habla.methods.audio.UtteranceGate;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * Speech recognition held to a JSGF grammar, type {@code speech-recognition}: the paper's way for a teacher
 * to talk to the Aibo. The recogniser is the {@code engine} param's ({@link SpeechEngine}): Sphinx-4
 * ({@link SphinxDecoder}) or Moonshine on ONNX Runtime ({@link MoonshineDecoder}); the voice-activity
 * detector, the cutting and trimming of utterances, the grammar and the rejection around it are the same for
 * both. Wire input {@code segments} to the utterances of {@code audio-processing}
 * (each chunk one utterance), or input {@code audio} to a microphone stream, which the method then
 * cuts into utterances itself with the same voice-activity detector; any rate and channel count
 * (resampled to the 16 kHz mono both engines' models need). Either way each utterance is trimmed to its
 * speech and a fixed margin ({@link UtteranceTrim}), so a recording handed over whole and the same
 * words cut from a stream are heard alike.
 *
 * <p>Each recognised phrase comes out on {@code words} as text and on {@code result} as a record
 * ({@code phrase}, {@code confidence} in (0, 1], {@code timeMs} the decoding time, {@code audioMs}
 * the utterance's length, {@code score} the engine's log score of the phrase, {@code engine}).
 * Each engine's confidence is its own, compared with its own threshold ({@code minConfidence} for
 * Sphinx-4, {@code moonshineMinConfidence} for Moonshine). What comes out is
 * always a whole phrase of the grammar: an utterance whose search ends in Sphinx's out-of-grammar
 * branch, or ends nowhere, gives nothing, and so does a phrase heard with less than
 * the engine's threshold. An utterance without {@code minVoicedMs} of voice in it (noise, a bang, a
 * whistled note) is not even decoded. With {@code adaptation} the model is first adapted to one
 * teacher's voice (an MLLR transform written by {@code habla enrol}).
 *
 * <p>The model loads in the background when the method starts (a few seconds; readiness is
 * "loading model" until then) and each utterance is decoded in the background, one at a time, so the
 * engine never waits for the recogniser. The status line ({@link SpeechStatus}) says what the chain has heard. Utterances that arrive meanwhile wait, up to {@code maxPending};
 * beyond that the oldest is dropped and counted, and so is one that waited longer than {@link #MAX_WAIT_MS} (a
 * command said while the model loaded is not said once it is ready).
 */
public final class SpeechRecognition extends ProcessingMethod {

    private static final int SPHINX_RATE_HZ = 16_000;
    /** Shorter than this no word fits; such audio is not worth a decoder's turn. */
    private static final int MIN_UTTERANCE_MS = 50;
    /** Prior of each phone of the free phone loop (Sphinx's out-of-grammar branch and the confidence search). */
    static final double PHONE_INSERTION = 0.05;

    /**
     * An utterance that waited longer than this for the decoder (while the model loaded, or behind a slow decoder)
     * is dropped, not decoded: a command said this late no longer fits what the robot is doing.
     */
    static final long MAX_WAIT_MS = 5_000;

    /** The pause after speech at which the utterance so far is decoded, in case it is over (audio input). */
    static final double SPECULATE_AFTER_MS = 30;

    private static final OutputPort<TextValue> WORDS = OutputPort.of("words", TextValue.class,
            Shape.text("the phrase of the grammar recognised in one utterance"));
    private static final OutputPort<RecordValue> RESULT = OutputPort.of("result", RecordValue.class,
            Shape.record("the recognised phrase with its confidence and decoding time", Recognition.LAYOUT));

    /**
     * An utterance waiting for the decoder, with the source time of its last audio and the engine time it was
     * queued at; a speculative one (the audio input's utterance so far, taken at a pause) carries its
     * {@link Speculation}.
     */
    private record Pending(AudioChunk audio, long sourceMicros, Speculation speculation, long arrivedMicros) {
    }

    /**
     * The decoding of the audio input's open utterance, taken at its first pause: said as soon as the
     * pause reaches {@code endpointMs}, dropped if speech resumes first.
     */
    private static final class Speculation {
        final long segment;
        final double loudMs;
        boolean decoded;
        boolean resumed;
        boolean decided;
        /** Set when the utterance ended before this was decoded: its end's time, and its whole audio. */
        Pending ended;
        double[] whole;
        Optional<SpeechEngine.Decoded> result = Optional.empty();

        Speculation(long segment, double loudMs) {
            this.segment = segment;
            this.loudMs = loudMs;
        }
    }

    private final SpeechRecognitionParams params;
    private final Output<TextValue> words = output(WORDS);
    private final Output<RecordValue> result = output(RESULT);
    private final ArrayDeque<Pending> pending = new ArrayDeque<>();
    private final VoiceCheck voice;

    private final SpeechStatus status;
    private SpeechEngine decoder;
    private boolean busy;
    /** Set when the method stops while an utterance is decoded: the decoding closes the engine when done. */
    private volatile boolean stopping;
    private AudioFormat streamFormat;
    private UtteranceGate gate;
    private Speculation speculation;
    private long early;
    /** The source time of the audio input's latest chunk. */
    private long lastMicros;

    SpeechRecognition(SpeechRecognitionParams params) {
        this.params = params;
        this.voice = new VoiceCheck(params.minVoicedMs());
        this.status = new SpeechStatus(params.engine());
        input(segments(params), this::onSegment);
        input(audio(params), this::onAudio);
    }

    /** The ports of a speech recognition whose input queues hold {@code queue} chunks. */
    static Ports ports(SpeechRecognitionParams params) {
        return Ports.of(segments(params), audio(params), WORDS, RESULT);
    }

    private static InputPort<AudioChunk> segments(SpeechRecognitionParams params) {
        return InputPort.optional("segments", AudioChunk.class, Delivery.queue(params.queue()));
    }

    private static InputPort<AudioChunk> audio(SpeechRecognitionParams params) {
        return InputPort.optional("audio", AudioChunk.class, Delivery.queue(params.queue()));
    }

    @Override
    protected void onStart() {
        readiness(false, "loading the " + params.engine() + " model");
        background("load the " + params.engine() + " model", () -> load(params), loaded -> {
            decoder = loaded;
            showStatus();
            decodeNext();
        });
    }

    /** Loads the engine the params name. */
    static SpeechEngine load(SpeechRecognitionParams p) throws java.io.IOException {
        if (p.engine().equals("moonshine")) {
            Path grammar = p.grammar().isEmpty() ? SphinxDecoder.bundledGrammar() : Path.of(p.grammar());
            return MoonshineDecoder.load(grammar, SpeechRecognitionParams.modelFolder(p.model()), p.threads(),
                    p.moonshineStepBonus());
        }
        return SphinxDecoder.load(settings(p), p.adaptationFile());
    }

    @Override
    protected void onStop() {
        stopping = true;
        if (decoder != null && !busy) {
            decoder.close();
        }
    }

    private void showStatus() {
        if (decoder != null) {
            readiness(true, status.line(gate == null || !gate.isOpen() ? -1 : gate.openMs(), pending.size()));
        }
    }

    private void onSegment(AudioChunk chunk, Sample sample) {
        double[] mono = MonoAudio.resample(MonoAudio.mix(chunk), chunk.format().sampleRateHz(), SPHINX_RATE_HZ);
        status.cut++;
        enqueue(mono, sample.sourceMicros(), null);
        showStatus();
    }

    private void onAudio(AudioChunk chunk, Sample sample) {
        lastMicros = sample.sourceMicros();
        if (!chunk.format().equals(streamFormat)) {
            streamFormat = chunk.format();
            gate = new UtteranceGate(streamFormat.sampleRateHz(), params.gate());
            speculation = null;
        }
        for (UtteranceGate.Segment segment : gate.offerSegments(MonoAudio.mix(chunk))) {
            status.cut++;
            double[] whole = MonoAudio.resample(segment.samples(), streamFormat.sampleRateHz(), SPHINX_RATE_HZ);
            Speculation s = speculation;
            if (s != null && s.segment == segment.number()) {
                speculation = null;
                if (!s.resumed && s.loudMs == segment.loudMs()) {
                    // the speculation heard the whole utterance: its result is the utterance's
                    if (s.decided) {
                        continue;
                    }
                    if (!s.decoded) {
                        s.ended = new Pending(null, sample.sourceMicros(), null, nowMicros());
                        s.whole = whole;
                        continue;
                    }
                    if (decide(s, sample.sourceMicros())) {
                        continue;
                    }
                } else {
                    s.resumed = true;
                }
            }
            enqueue(whole, sample.sourceMicros(), null);
        }
        speculate(sample.sourceMicros());
        showStatus();
    }

    /**
     * While the hangover runs: decodes the utterance so far at its first pause, drops that decoding if
     * speech resumes, and says its phrase once the pause reaches {@code endpointMs}.
     */
    private void speculate(long sourceMicros) {
        if (params.endpointMs() >= params.hangoverMs() || !gate.isOpen()) {
            return;
        }
        Speculation s = speculation;
        if (s != null && (s.segment != gate.segmentNumber() || gate.loudMs() > s.loudMs)) {
            s.resumed = true;
            speculation = null;
            s = null;
        }
        if (s == null && gate.quietMs() >= SPECULATE_AFTER_MS
                && gate.peakAboveFloorDb() >= params.endpointAboveFloorDb()) {
            s = new Speculation(gate.segmentNumber(), gate.loudMs());
            speculation = s;
            double[] soFar = MonoAudio.resample(gate.soFar(), streamFormat.sampleRateHz(), SPHINX_RATE_HZ);
            if (!enqueue(soFar, sourceMicros, s)) {
                // nothing worth decoding yet: the utterance is decoded whole when it ends
                s.decoded = true;
            }
            return;
        }
        if (s != null && s.decoded && !s.decided && gate.quietMs() >= params.endpointMs()) {
            decide(s, sourceMicros);
        }
    }

    /**
     * Says a speculation's phrase if it has one with confidence enough; returns whether it did. A
     * speculation that heard nothing leaves the utterance to be decoded whole when it ends.
     */
    private boolean decide(Speculation s, long sourceMicros) {
        if (s.result.isEmpty() || s.result.get().confidence() < params.engineMinConfidence()) {
            return false;
        }
        s.decided = true;
        if (s == speculation && gate.isOpen() && gate.segmentNumber() == s.segment) {
            // the phrase is over: what the speaker says next is a new utterance
            gate.cut();
            speculation = null;
            early++;
        }
        publish(s.result.get(), s.result.get().audioMs(), sourceMicros);
        return true;
    }

    /** Trims and checks an utterance and queues it for the decoder; false if it is not worth decoding. */
    private boolean enqueue(double[] whole, long sourceMicros, Speculation speculation) {
        double[] mono16k = UtteranceTrim.trim(whole, SPHINX_RATE_HZ);
        if (mono16k.length < SPHINX_RATE_HZ * MIN_UTTERANCE_MS / 1000) {
            return false;
        }
        if (!voice.hasVoice(mono16k, SPHINX_RATE_HZ)) {
            if (speculation == null) {
                status.unvoiced++;
                log().debug("{}: an utterance without a voice in it is not decoded ({} so far)", id(), status.unvoiced);
            }
            return false;
        }
        AudioChunk utterance = MonoAudio.chunk(mono16k, SPHINX_RATE_HZ);
        pending.addLast(new Pending(utterance, sourceMicros, speculation, nowMicros()));
        while (pending.size() > params.maxPending()) {
            pending.removeFirst();
            status.dropped++;
            log().warn("{}: {} utterances dropped so far: more arrive than {} decodes (maxPending {})", id(),
                    status.dropped, params.engine(), params.maxPending());
        }
        decodeNext();
        return true;
    }

    private void decodeNext() {
        if (decoder == null || busy) {
            return;
        }
        while (!pending.isEmpty()) {
            Pending first = pending.peekFirst();
            Speculation s = first.speculation();
            if (s != null && (s.resumed || s.decided)) {
                // a speculation overtaken by the speaker is not worth the decoder's time
                pending.removeFirst();
            } else if (nowMicros() - first.arrivedMicros() > MAX_WAIT_MS * 1000) {
                pending.removeFirst();
                status.late++;
                if (s != null) {
                    // the utterance it belongs to is as late: it is not decoded whole either
                    s.decoded = true;
                    s.decided = true;
                }
                log().warn("{}: {} utterances dropped so far: waited over {} ms for {} (the model loading, or a slow "
                        + "decoder)", id(), status.late, MAX_WAIT_MS, params.engine());
            } else {
                break;
            }
        }
        if (pending.isEmpty()) {
            return;
        }
        busy = true;
        Pending next = pending.removeFirst();
        SpeechEngine d = decoder;
        background("recognise an utterance", () -> decodeOrSkip(d, next.audio()), decoded -> {
            busy = false;
            status.decoded++;
            decoded.ifPresent(r -> status.decodeTook(r.decodeMs()));
            Speculation s = next.speculation();
            if (s != null) {
                s.decoded = true;
                s.result = decoded;
                if (!s.resumed && !s.decided) {
                    if (s.ended != null) {
                        // the utterance ended while this was decoded: its phrase, or else the whole utterance decoded
                        if (!decide(s, s.ended.sourceMicros())) {
                            s.decided = true;
                            enqueue(s.whole, s.ended.sourceMicros(), null);
                            return;
                        }
                    } else if (s == speculation && gate.quietMs() >= params.endpointMs()) {
                        decide(s, lastMicros);
                    }
                }
                decodeNext();
                return;
            }
            if (decoded.isEmpty()) {
                status.noPhrase++;
            }
            decoded.ifPresent(r -> {
                if (r.confidence() >= params.engineMinConfidence()) {
                    publish(r, r.audioMs(), next.sourceMicros());
                } else {
                    status.lowConfidence++;
                    log().debug("{}: '{}' heard with confidence {} < {}: nothing said", id(), r.phrase(),
                            r.confidence(), params.engineMinConfidence());
                }
            });
            decodeNext();
            showStatus();
        });
    }

    /**
     * Decodes on the engine's pool. An utterance Sphinx chokes on is skipped with a warning rather than
     * failing the method: the next one may be fine, and the teacher keeps talking.
     */
    private Optional<SpeechEngine.Decoded> decodeOrSkip(SpeechEngine d, AudioChunk utterance) {
        try {
            return d.decode(utterance);
        } catch (RuntimeException e) {
            log().warn("{}: {} could not decode an utterance of {} ms, skipped: {}", id(), d.name(),
                    utterance.frameCount() * 1000L / SPHINX_RATE_HZ, e.toString());
            return Optional.empty();
        } finally {
            if (stopping) {
                d.close();
            }
        }
    }

    private void publish(SpeechEngine.Decoded r, long audioMs, long sourceMicros) {
        status.said++;
        emit(words, new TextValue(r.phrase()), sourceMicros);
        emit(result, RecordValue.of(new Recognition(r.phrase(), Math.round(r.confidence() * 1000) / 1000.0,
                r.decodeMs(), audioMs, r.score(), decoder.name())), sourceMicros);
    }

    /** Phrases said at an early endpoint, before the hangover ended the utterance. */
    public long earlyPhrases() {
        return early;
    }

    /** Utterances dropped because too many waited. */
    public long droppedUtterances() {
        return status.dropped;
    }

    /** Utterances dropped because they waited longer than {@link #MAX_WAIT_MS} for the decoder. */
    public long lateUtterances() {
        return status.late;
    }

    /** Utterances not decoded because they held no voice. */
    public long unvoicedUtterances() {
        return status.unvoiced;
    }

    /** Utterances whose phrase was heard with too little confidence. */
    public long rejectedUtterances() {
        return status.lowConfidence;
    }

    /** The decoder's settings from the params (the bundled grammar copied to a file when none is named). */
    static SphinxDecoder.Settings settings(SpeechRecognitionParams p) throws java.io.IOException {
        Path grammar = p.grammar().isEmpty() ? SphinxDecoder.bundledGrammar() : Path.of(p.grammar());
        return new SphinxDecoder.Settings(grammar, p.denoise(), p.outOfGrammarProbability(), PHONE_INSERTION,
                p.garbagePrior());
    }

    /** Utterances in which a phrase was recognised. */
    public long recognisedUtterances() {
        return status.said;
    }

    /** Makes {@code speech-recognition} methods. */
    public static final class Provider extends SimpleMethodProvider<SpeechRecognitionParams> {
        public Provider() {
            super("speech-recognition", "Recognises spoken phrases of a grammar with Sphinx-4 or Moonshine",
                    SpeechRecognitionParams.class, SpeechRecognition::ports, (layer, p) -> new SpeechRecognition(p),
                    Layer.PROCESSING);
        }
    }
}
