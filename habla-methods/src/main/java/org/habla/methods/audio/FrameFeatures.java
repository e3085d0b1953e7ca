package org.habla.methods.audio;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.Arrays;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * What one frame of sound looks like: its level, its pitch and a coarse spectrum. Published by
 * {@code audio-processing} as the {@code audio-features} record, its level and pitch to a hundredth and its bands to
 * a tenth.
 *
 * @param rms      root mean square of the frame, full scale = 1
 * @param db       the RMS in dB relative to full scale (a full-scale sine is −3 dB), at least −120
 * @param pitchHz  fundamental frequency, 0 when the frame is not periodic
 * @param voiced   periodic and loud enough to be a voice or a tone
 * @param spectrum mean power of each band, equal-width bands from 0 Hz to half the sample rate,
 *                 in dB on the same scale as {@code db} (the band powers add up to the frame's power)
 */
public record FrameFeatures(double rms, double db, double pitchHz, boolean voiced, double[] spectrum)
        implements RecordForm {

    /** The fields of an audio-features record. */
    public static final RecordLayout<FrameFeatures> LAYOUT = RecordLayout.of(FrameFeatures.class)
            .number("rms", FrameFeatures::rms).doc("root mean square of the frame, full scale = 1")
            .number("db", FrameFeatures::db).unit("dBFS").doc("the frame's level; a full-scale sine is -3 dB")
            .number("pitchHz", FrameFeatures::pitchHz).unit("Hz").doc("fundamental frequency, 0 when not periodic")
            .flag("voiced", FrameFeatures::voiced).doc("periodic and loud enough to be a voice or a tone")
            .array("spectrum", FrameFeatures::spectrumJson).unit("dBFS")
            .frame("equal-width bands from 0 Hz to half the sample rate").doc("mean power of each band")
            .build();

    @Override
    public RecordLayout<FrameFeatures> layout() {
        return LAYOUT;
    }

    /** The record the {@code features} output carries: level and pitch to a hundredth, bands to a tenth. */
    public RecordValue toRecord() {
        double[] bands = new double[spectrum.length];
        for (int i = 0; i < bands.length; i++) {
            bands[i] = Math.round(spectrum[i] * 10) / 10.0;
        }
        return RecordValue.of(new FrameFeatures(rms, Math.round(db * 100) / 100.0, Math.round(pitchHz * 100) / 100.0,
                voiced, bands));
    }

    /**
     * The features a record carries: the form itself inside the daemon, else read from its JSON, where a level that
     * is not a finite number is NaN, a pitch that is not one is 0 and a missing voiced flag is false.
     */
    public static FrameFeatures fromRecord(RecordValue record) {
        return record.as(FrameFeatures.class, r -> {
            JsonNode db = r.get("db");
            JsonNode pitch = r.get("pitchHz");
            JsonNode rms = r.get("rms");
            return new FrameFeatures(rms.isNumber() ? rms.doubleValue() : Double.NaN,
                    db.isNumber() && Double.isFinite(db.doubleValue()) ? db.doubleValue() : Double.NaN,
                    pitch.isNumber() && Double.isFinite(pitch.doubleValue()) ? pitch.doubleValue() : 0,
                    r.get("voiced").asBoolean(false), new double[0]);
        });
    }

    private JsonNode spectrumJson() {
        ArrayNode bands = JsonNodeFactory.instance.arrayNode(spectrum.length);
        for (double b : spectrum) {
            bands.add(b);
        }
        return bands;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof FrameFeatures f && Double.compare(f.rms, rms) == 0 && Double.compare(f.db, db) == 0
                && Double.compare(f.pitchHz, pitchHz) == 0 && f.voiced == voiced && Arrays.equals(f.spectrum, spectrum);
    }

    @Override
    public int hashCode() {
        return Double.hashCode(db) * 31 + Arrays.hashCode(spectrum);
    }

    @Override
    public String toString() {
        return "FrameFeatures[rms=" + rms + ", db=" + db + ", pitchHz=" + pitchHz + ", voiced=" + voiced + ", spectrum="
                + Arrays.toString(spectrum) + "]";
    }
}
