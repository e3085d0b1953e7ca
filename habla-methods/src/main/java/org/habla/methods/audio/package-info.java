/**
 * Sound analysis shared by the audio methods: mono mixing and resampling, a fast Fourier transform,
 * pitch estimation, per-frame features and the energy gate that cuts utterances and tones out of a
 * stream; plus the {@code audio-processing} method that publishes them.
 */
package org.habla.methods.audio;
