package org.habla.methods.audio;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import org.habla.sample.RecordValue;

/**
 * What one frame of sound looks like: its level, its pitch and a coarse spectrum. Published by
 * {@code audio-processing} as the {@code audio-features} record.
 *
 * @param rms      root mean square of the frame, full scale = 1
 * @param db       the RMS in dB relative to full scale (a full-scale sine is −3 dB), at least −120
 * @param pitchHz  fundamental frequency, 0 when the frame is not periodic
 * @param voiced   periodic and loud enough to be a voice or a tone
 * @param spectrum mean power of each band, equal-width bands from 0 Hz to half the sample rate,
 *                 in dB on the same scale as {@code db} (the band powers add up to the frame's power)
 */
public record FrameFeatures(double rms, double db, double pitchHz, boolean voiced, double[] spectrum) {

    /** The record the {@code features} output carries. */
    public RecordValue toRecord() {
        ArrayNode bands = JsonNodeFactory.instance.arrayNode();
        for (double b : spectrum) {
            bands.add(Math.round(b * 10) / 10.0);
        }
        return RecordValue.builder()
                .put("rms", rms)
                .put("db", Math.round(db * 100) / 100.0)
                .put("pitchHz", Math.round(pitchHz * 100) / 100.0)
                .put("voiced", voiced)
                .set("spectrum", bands)
                .build();
    }
}
