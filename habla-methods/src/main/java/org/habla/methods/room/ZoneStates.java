package org.habla.methods.room;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/** The records of the room's zones: which zones are occupied ({@code occupancy}) and how light each one is. */
final class ZoneStates {

    private ZoneStates() {
    }

    /**
     * The {@code occupancy} record: each zone's presence (1 or 0), the occupied zones and their count.
     *
     * @param zones    each zone, in the config's order: 1 while someone is there, else 0
     * @param occupied the occupied zones, in the config's order
     */
    record Occupied(Map<String, Integer> zones, List<String> occupied) implements RecordForm {

        static final RecordLayout<Occupied> LAYOUT = RecordLayout.of(Occupied.class)
                .object("zones", o -> object(o.zones)).doc("each zone: 1 while someone is there, else 0")
                .texts("occupied", Occupied::occupied).doc("the occupied zones")
                .longInteger("count", o -> o.occupied.size()).doc("how many zones are occupied")
                .build();

        Occupied {
            zones = Collections.unmodifiableMap(new LinkedHashMap<>(zones));
            occupied = List.copyOf(occupied);
        }

        @Override
        public RecordLayout<Occupied> layout() {
            return LAYOUT;
        }
    }

    /**
     * The {@code light} record: each zone's illuminance, once heard, and the zones darker than {@code darkLux}.
     *
     * @param lux  each zone heard so far, in the config's order
     * @param dark the zones darker than darkLux
     */
    record Light(Map<String, Double> lux, List<String> dark) implements RecordForm {

        static final RecordLayout<Light> LAYOUT = RecordLayout.of(Light.class)
                .object("lux", l -> object(l.lux)).unit("lx").doc("each zone's illuminance, once heard")
                .texts("dark", Light::dark).doc("the zones darker than darkLux")
                .build();

        Light {
            lux = Collections.unmodifiableMap(new LinkedHashMap<>(lux));
            dark = List.copyOf(dark);
        }

        @Override
        public RecordLayout<Light> layout() {
            return LAYOUT;
        }
    }

    private static JsonNode object(Map<String, ? extends Number> values) {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        values.forEach((k, v) -> {
            if (v instanceof Integer i) {
                o.put(k, i);
            } else {
                o.put(k, v.doubleValue());
            }
        });
        return o;
    }

}
