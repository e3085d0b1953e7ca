package org.habla.methods.room;

import java.util.List;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code comfort} record of {@code comfort}: the readings heard so far, a score and what is wrong.
 *
 * @param temperatureC the air temperature, or null while unknown
 * @param humidityPct  the relative humidity, or null while unknown
 * @param lux          the illuminance, or null while unknown
 * @param soundDb      the sound level, or null while unknown
 * @param score        the share of the readings heard that are within their comfortable range, 1 when none is heard
 * @param complaints   what is wrong: cold, warm, dry, humid, dark, glaring, noisy
 */
public record ComfortReport(Double temperatureC, Double humidityPct, Double lux, Double soundDb, double score,
        List<String> complaints) implements RecordForm {

    /** The fields of a comfort record. */
    public static final RecordLayout<ComfortReport> LAYOUT = RecordLayout.of(ComfortReport.class)
            .optionalNumber("temperatureC", ComfortReport::temperatureC).unit("°C").doc("the air temperature")
            .optionalNumber("humidityPct", ComfortReport::humidityPct).unit("%").doc("the relative humidity")
            .optionalNumber("lux", ComfortReport::lux).unit("lx").doc("the illuminance")
            .optionalNumber("soundDb", ComfortReport::soundDb).unit("dB").doc("the sound level")
            .number("score", ComfortReport::score).doc("the share of the readings heard that are comfortable, 0..1")
            .texts("complaints", ComfortReport::complaints)
            .doc("what is wrong: cold, warm, dry, humid, dark, glaring, noisy")
            .build();

    public ComfortReport {
        complaints = List.copyOf(complaints);
    }

    @Override
    public RecordLayout<ComfortReport> layout() {
        return LAYOUT;
    }

}
