package org.habla.methods.speech;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.MethodHarness;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The speech chain of a config, run in memory: {@code audio-processing} cutting utterances out of a
 * microphone stream, {@code speech-recognition} on each, made by the registry from the config's own
 * entries and params. The stream is handed over in chunks as a microphone delivers it; what comes out
 * is stamped with the stream time of the chunk that ended the utterance.
 */
public final class SpeechChain {

    /** What the chain said, and when: the stream time (s) of the audio that ended the utterance. */
    public record Heard(String phrase, double confidence, double atS, double decodeMs) {
    }

    private static final long BASE_MICROS = 1_000_000_000L;

    private final MethodProvider<?> audioProvider;
    private final Record audioParams;
    private final MethodHarness speech;
    private final boolean direct;

    private SpeechChain(MethodProvider<?> audioProvider, Record audioParams, Method speech, boolean direct) {
        this.audioProvider = audioProvider;
        this.audioParams = audioParams;
        this.direct = direct;
        this.speech = MethodHarness.started("speech", speech);
        while (!this.speech.ready()) {
            if (this.speech.runBackground() == 0) {
                throw new IllegalStateException("speech-recognition did not load: " + this.speech.readinessDetail());
            }
        }
        this.speech.runBackgroundAtOnce();
    }

    /** The chain of methods {@code audioId} and {@code speechId} of the config file, model loaded. */
    public static SpeechChain fromConfig(Path config, String audioId, String speechId) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(config);
        MethodConfig audio = c.method(audioId).orElseThrow(() -> new IOException(config + " has no method " + audioId));
        MethodConfig speech = c.method(speechId).orElseThrow(() -> new IOException(config + " has no method " + speechId));
        MethodProvider<?> ap = registry.method(audio.type()).orElseThrow();
        return new SpeechChain(ap, audio.params(), create(registry.method(speech.type()).orElseThrow(), speech.params()),
                direct(speech));
    }

    /** Whether the config hands the microphone's stream to speech-recognition's own audio input. */
    public static boolean direct(MethodConfig speech) {
        return speech.inputs().containsKey("audio");
    }

    /**
     * The chain of the config with some params changed (for tuning): system properties {@code ap.NAME}
     * for {@code audio-processing}, {@code sr.NAME} for {@code speech-recognition}.
     */
    public static SpeechChain fromConfigWithOverrides(Path config, String audioId, String speechId) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig c = new ConfigLoader(registry).load(config);
        MethodConfig audio = c.method(audioId).orElseThrow();
        MethodConfig speech = c.method(speechId).orElseThrow();
        return of(override(audio.params(), "ap."), override(speech.params(), "sr."), direct(speech));
    }

    private static Record override(Record r, String prefix) throws Exception {
        var components = r.getClass().getRecordComponents();
        Object[] values = new Object[components.length];
        Class<?>[] types = new Class<?>[components.length];
        for (int i = 0; i < components.length; i++) {
            types[i] = components[i].getType();
            values[i] = components[i].getAccessor().invoke(r);
            String v = System.getProperty(prefix + components[i].getName());
            if (v != null) {
                Class<?> t = types[i];
                values[i] = t == Double.class || t == double.class ? Double.valueOf(v)
                        : t == Integer.class || t == int.class ? Integer.valueOf(v)
                        : t == Boolean.class || t == boolean.class ? Boolean.valueOf(v) : v;
                System.out.println("  " + prefix + components[i].getName() + " = " + v);
            }
        }
        return (Record) r.getClass().getDeclaredConstructor(types).newInstance(values);
    }

    /** The chain with explicit params, audio-processing's segments feeding speech-recognition. */
    public static SpeechChain of(Record audioParams, Record speechParams) {
        return of(audioParams, speechParams, false);
    }

    /**
     * The chain with explicit params (for tuning): {@code direct}, the stream goes to speech-recognition's
     * audio input; otherwise audio-processing's segments do.
     */
    public static SpeechChain of(Record audioParams, Record speechParams, boolean direct) {
        PluginRegistry registry = PluginRegistry.discover();
        return new SpeechChain(registry.method("audio-processing").orElseThrow(), audioParams,
                create(registry.method("speech-recognition").orElseThrow(), speechParams), direct);
    }

    private static <P extends Record> Method create(MethodProvider<P> provider, Record params) {
        return provider.create(Layer.PROCESSING, provider.paramsType().cast(params));
    }

    /** Runs one stream (any format) through a fresh {@code audio-processing} and this chain's recogniser. */
    public List<Heard> run(AudioChunk stream, int chunkMs) {
        MethodHarness audio = MethodHarness.started("audio", create(audioProvider, audioParams)).runBackgroundAtOnce();
        speech.clear();
        if (direct) {
            // a new stream: the recogniser's endpointing starts afresh, as when a microphone's format changes
            speech.push("audio", AudioChunk.wrap(new org.habla.sample.AudioFormat(8_000, 1, 16), new byte[2]));
        }
        int frame = stream.format().frameBytes();
        int chunkFrames = stream.format().sampleRateHz() * chunkMs / 1000;
        byte[] pcm = stream.pcm();
        double rate = stream.format().sampleRateHz();
        for (int at = 0; at < stream.frameCount(); at += chunkFrames) {
            int end = Math.min(stream.frameCount(), at + chunkFrames);
            byte[] part = java.util.Arrays.copyOfRange(pcm, at * frame, end * frame);
            long micros = BASE_MICROS + Math.round(end / rate * 1e6);
            if (direct) {
                speech.push("audio", AudioChunk.wrap(stream.format(), part), micros);
                continue;
            }
            audio.push("audio", AudioChunk.wrap(stream.format(), part), micros);
            for (Sample s : audio.samples("segments")) {
                speech.push("segments", s.payload(), s.sourceMicros());
            }
            audio.clear();
        }
        List<Heard> heard = new ArrayList<>();
        for (Sample s : speech.samples("result")) {
            RecordValue r = (RecordValue) s.payload();
            heard.add(new Heard(r.text("phrase"), r.has("confidence") ? r.number("confidence") : Double.NaN,
                    (s.sourceMicros() - BASE_MICROS) / 1e6, r.has("timeMs") ? r.number("timeMs") : Double.NaN));
        }
        return heard;
    }

    /** The recogniser's harness (to read its counters or push whole utterances). */
    public MethodHarness speech() {
        return speech;
    }
}
