package org.habla.methods.room;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The {@code climate} record of {@code climate-sensor}: the air's temperature and relative humidity, each once it
 * has been read.
 *
 * @param temperatureC the air temperature, or null before the first reading
 * @param humidityPct  the relative humidity, or null before the first reading
 */
public record Climate(Double temperatureC, Double humidityPct) implements RecordForm {

    /** The fields of a climate record. */
    public static final RecordLayout<Climate> LAYOUT = RecordLayout.of(Climate.class)
            .optionalNumber("temperatureC", Climate::temperatureC).unit("°C").doc("the air temperature")
            .optionalNumber("humidityPct", Climate::humidityPct).unit("%").doc("the relative humidity")
            .build();

    @Override
    public RecordLayout<Climate> layout() {
        return LAYOUT;
    }

    /** The climate a record carries: the form itself inside the daemon, else the numbers its JSON has. */
    public static Climate fromRecord(RecordValue record) {
        return record.as(Climate.class, r -> new Climate(number(r.get("temperatureC")), number(r.get("humidityPct"))));
    }

    private static Double number(JsonNode n) {
        return n.isNumber() ? n.doubleValue() : null;
    }
}
