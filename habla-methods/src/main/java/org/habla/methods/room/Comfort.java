package org.habla.methods.room;

import java.util.ArrayList;
import java.util.List;
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
 * The comfort method, type {@code comfort}: how pleasant a room is for a person, from its climate (input
 * {@code climate}: {@code temperatureC}, {@code humidityPct}), light (input {@code lux}) and noise (input
 * {@code sound}, dB). Output {@code comfort} is a record of the readings, a {@code score} from 0 (everything
 * out of range) to 1 (everything within), and the {@code complaints}: {@code cold}, {@code warm}, {@code dry},
 * {@code humid}, {@code dark}, {@code glaring}, {@code noisy}. Each reading counts only once it has been heard;
 * every input may be left unwired.
 */
public final class Comfort extends VirtualMethod {

    private static final InputPort<RecordValue> CLIMATE = InputPort.optional("climate", RecordValue.class,
            Delivery.latest());
    private static final InputPort<NumberValue> LUX = InputPort.optional("lux", NumberValue.class, Delivery.latest());
    private static final InputPort<NumberValue> SOUND = InputPort.optional("sound", NumberValue.class,
            Delivery.latest());
    private static final OutputPort<RecordValue> COMFORT = OutputPort.of("comfort", RecordValue.class,
            Shape.record("the readings, a score 0..1 and what is wrong", ComfortReport.LAYOUT));
    static final Ports PORTS = Ports.of(CLIMATE, LUX, SOUND, COMFORT);

    private final Params params;
    private final Output<RecordValue> comfort = output(COMFORT);
    private Double temperatureC;
    private Double humidityPct;
    private Double lux;
    private Double soundDb;

    /** The params of a {@code comfort} method: the comfortable ranges. */
    public record Params(
            @Param(value = "coldest comfortable air", unit = "degC", defaultValue = "20",
                    min = -40, max = 85)
            double minTemperatureC,
            @Param(value = "warmest comfortable air", unit = "degC", defaultValue = "25",
                    min = -40, max = 85)
            double maxTemperatureC,
            @Param(value = "driest comfortable air", unit = "%", defaultValue = "30",
                    min = 0, max = 100)
            double minHumidityPct,
            @Param(value = "most humid comfortable air", unit = "%", defaultValue = "60",
                    min = 0, max = 100)
            double maxHumidityPct,
            @Param(value = "least light to read or work by", unit = "lx", defaultValue = "200",
                    min = 0, max = 1e6)
            double minLux,
            @Param(value = "most light before it glares", unit = "lx", defaultValue = "2000",
                    min = 0, max = 1e6)
            double maxLux,
            @Param(value = "loudest comfortable sound", unit = "dB", defaultValue = "-20",
                    min = -200, max = 200)
            double maxSoundDb) {

        public Params {
            atLeast("maxTemperatureC", maxTemperatureC, "minTemperatureC", minTemperatureC);
            atLeast("maxHumidityPct", maxHumidityPct, "minHumidityPct", minHumidityPct);
            atLeast("maxLux", maxLux, "minLux", minLux);
        }

        private static void atLeast(String name, double value, String lowName, double low) {
            if (value < low) {
                throw new IllegalArgumentException(name + " must be at least " + lowName + " (" + low + "), was " + value);
            }
        }
    }

    Comfort(Params params) {
        this.params = params;
        input(CLIMATE, this::onClimate);
        input(LUX, (v, s) -> {
            lux = v.value();
            publish();
        });
        input(SOUND, (v, s) -> {
            soundDb = v.value();
            publish();
        });
    }

    private void onClimate(RecordValue value, Sample sample) {
        Climate climate = Climate.fromRecord(value);
        if (climate.temperatureC() != null) {
            temperatureC = climate.temperatureC();
        }
        if (climate.humidityPct() != null) {
            humidityPct = climate.humidityPct();
        }
        publish();
    }

    private void publish() {
        List<String> complaints = new ArrayList<>();
        int heard = 0;
        heard += check(temperatureC, params.minTemperatureC(), params.maxTemperatureC(), "cold", "warm", complaints);
        heard += check(humidityPct, params.minHumidityPct(), params.maxHumidityPct(), "dry", "humid", complaints);
        heard += check(lux, params.minLux(), params.maxLux(), "dark", "glaring", complaints);
        heard += check(soundDb, Double.NEGATIVE_INFINITY, params.maxSoundDb(), "", "noisy", complaints);
        emit(comfort, RecordValue.of(new ComfortReport(temperatureC, humidityPct, lux, soundDb,
                heard == 0 ? 1 : 1 - complaints.size() / (double) heard, complaints)));
    }

    private static int check(Double v, double min, double max, String low, String high, List<String> complaints) {
        if (v == null) {
            return 0;
        }
        if (v < min) {
            complaints.add(low);
        } else if (v > max) {
            complaints.add(high);
        }
        return 1;
    }

    /** Makes {@code comfort} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("comfort", "How pleasant a room is: its climate, light and noise against comfortable ranges",
                    Params.class, PORTS, (layer, p) -> new Comfort(p), Layer.VIRTUAL);
        }
    }
}
