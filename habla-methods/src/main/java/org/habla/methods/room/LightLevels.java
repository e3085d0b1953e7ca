package org.habla.methods.room;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.plugin.Param;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The light levels method, type {@code light-levels}: how light every zone of a room is. One input per zone the
 * {@code zones} param names (illuminance in lux) and one output, {@code light}:
 * {@code {"lux": {"desk": 412, "sofa": 95}, "dark": ["sofa"]}}, where a zone is dark below {@code darkLux}. Sent
 * whenever a zone's reading comes; a zone not heard from yet is left out.
 */
public final class LightLevels extends VirtualMethod {

    private static final OutputPort<RecordValue> LIGHT = OutputPort.of("light", RecordValue.class,
            Shape.record("every zone's illuminance (lx) and the zones darker than darkLux",
                    ZoneStates.Light.LAYOUT));

    private final Params params;
    private final Output<RecordValue> light = output(LIGHT);
    private final Map<String, Double> lux = new LinkedHashMap<>();

    /** The params of a {@code light-levels} method. */
    public record Params(
            @Param("the zones, each an input of the method (letters, digits, '_', '-')") List<String> zones,
            @Param(value = "a zone is dark below this", unit = "lx", defaultValue = "200",
                    min = 0, max = 1e6)
            double darkLux) {

        public Params {
            zones = new Occupancy.Params(zones, 0).zones();
        }
    }

    LightLevels(Params params) {
        this.params = params;
        for (String zone : params.zones()) {
            input(zone(zone), (value, sample) -> onLux(zone, value, sample));
        }
    }

    /** The ports of a method with these zones: one input per zone. */
    static Ports ports(Params params) {
        return Ports.of(LIGHT).plus(params.zones().stream().map(LightLevels::zone).toList());
    }

    private static InputPort<NumberValue> zone(String name) {
        return InputPort.of(name, NumberValue.class, Delivery.latest());
    }

    private void onLux(String zone, NumberValue value, Sample sample) {
        if (!Double.isFinite(value.value())) {
            return;
        }
        lux.put(zone, value.value());
        Map<String, Double> levels = new LinkedHashMap<>();
        List<String> dark = new ArrayList<>();
        for (String z : params.zones()) {
            Double v = lux.get(z);
            if (v != null) {
                levels.put(z, v);
                if (v < params.darkLux()) {
                    dark.add(z);
                }
            }
        }
        emit(light, RecordValue.of(new ZoneStates.Light(levels, dark)));
    }

    /** Makes {@code light-levels} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("light-levels", "How light every zone of a room is, and which zones are dark", Params.class,
                    LightLevels::ports, (layer, p) -> new LightLevels(p), Layer.VIRTUAL);
        }
    }
}
