package org.habla.methods.speech;

import java.util.Optional;
import org.habla.sample.AudioChunk;

/**
 * A recogniser behind {@code speech-recognition}: it hears one whole utterance (16 kHz mono 16-bit,
 * already cut by the voice-activity detector and trimmed) and names the phrase of the grammar it holds,
 * or nothing. Whatever the engine, what it names is always a whole phrase of the method's grammar.
 *
 * <p>The method calls {@link #decode} on the engine's background pool, one utterance at a time: an engine
 * need not be safe for two callers at once.
 */
public interface SpeechEngine extends AutoCloseable {

    /**
     * One utterance's phrase: {@code confidence} in (0, 1] (how each engine measures it is its own:
     * compare it with that engine's threshold only), {@code score} the engine's own score of the phrase,
     * the decoding time and the utterance's length.
     */
    record Decoded(String phrase, double confidence, double score, long decodeMs, long audioMs) {
    }

    /** The engine's name as a config names it ({@code sphinx4}, {@code moonshine}). */
    String name();

    /** The phrase of the grammar that {@code utterance} holds, or empty when it holds none. */
    Optional<Decoded> decode(AudioChunk utterance);

    /** Frees what the engine holds (native sessions, threads); the engine is not used again. */
    @Override
    default void close() {
    }
}
