/**
 * Speech benchmarks: {@link org.habla.bench.speech.SpeechBench} ({@code bench/run speech}) scores the speech chain on
 * the held-out voices of the evaluation set, {@link org.habla.bench.speech.SpeechTuning} on the tune voices.
 */
package org.habla.bench.speech;
