package org.habla.methods.room;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
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
 * The occupancy method, type {@code occupancy}: which zones of a room someone is in. It has one input per zone
 * the {@code zones} param names (each a presence, 1 or 0) and one output, {@code occupancy}:
 * {@code {"zones": {"desk": 1, "sofa": 0}, "occupied": ["desk"], "count": 1}}, sent whenever a zone's presence
 * comes and again every {@code periodMs} (so a client that joins late, or a daemon listening through a broker, has
 * the state without waiting for someone to move). A zone not heard from yet counts as empty.
 */
public final class Occupancy extends VirtualMethod {

    private static final Pattern ZONE = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,31}");
    private static final OutputPort<RecordValue> OCCUPANCY = OutputPort.of("occupancy", RecordValue.class,
            Shape.record("the presence of every zone, the occupied zones and their count", ZoneStates.Occupied.LAYOUT));

    private final Output<RecordValue> occupancy = output(OCCUPANCY);
    private final Map<String, Boolean> present = new LinkedHashMap<>();
    private boolean heard;

    /** The params of an {@code occupancy} method. */
    public record Params(
            @Param("the zones, each an input of the method (letters, digits, '_', '-')") List<String> zones,
            @Param(value = "the state is sent again this often; 0: only when a presence comes", unit = "ms",
                    defaultValue = "1000", min = 0, max = 3_600_000) int periodMs) {

        public Params {
            if (zones == null || zones.isEmpty()) {
                throw new IllegalArgumentException("zones: name at least one zone");
            }
            zones = List.copyOf(zones);
            if (zones.size() > 64) {
                throw new IllegalArgumentException("zones: at most 64 zones, " + zones.size() + " given");
            }
            if (zones.stream().distinct().count() != zones.size()) {
                throw new IllegalArgumentException("zones: a zone is named twice in " + zones);
            }
            for (String z : zones) {
                if (!ZONE.matcher(z).matches()) {
                    throw new IllegalArgumentException("zones: '" + z + "' must be a letter, then letters, digits, "
                            + "'_' or '-'");
                }
            }
        }
    }

    Occupancy(Params params) {
        for (String zone : params.zones()) {
            present.put(zone, false);
            input(zone(zone), (value, sample) -> onPresence(zone, value, sample));
        }
        if (params.periodMs() > 0) {
            tickEvery(java.time.Duration.ofMillis(params.periodMs()));
        }
    }

    /** The ports of a method with these zones: one input per zone. */
    static Ports ports(Params params) {
        return Ports.of(OCCUPANCY).plus(params.zones().stream().map(Occupancy::zone).toList());
    }

    private static InputPort<NumberValue> zone(String name) {
        return InputPort.of(name, NumberValue.class, Delivery.queue(16));
    }

    private void onPresence(String zone, NumberValue value, Sample sample) {
        present.put(zone, value.value() >= 0.5);
        publish();
        heard = true;
    }

    @Override
    protected void onTick(long nowMicros) {
        if (heard) {
            publish();
        }
    }

    private void publish() {
        Map<String, Integer> zones = new LinkedHashMap<>();
        List<String> occupied = new ArrayList<>();
        present.forEach((z, p) -> {
            zones.put(z, p ? 1 : 0);
            if (p) {
                occupied.add(z);
            }
        });
        emit(occupancy, RecordValue.of(new ZoneStates.Occupied(zones, occupied)));
    }

    /** Makes {@code occupancy} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("occupancy", "Which zones of a room someone is in, from one presence input per zone", Params.class,
                    Occupancy::ports, (layer, p) -> new Occupancy(p), Layer.VIRTUAL);
        }
    }
}
