package org.habla.methods.room;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.NoParams;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The climate sensor method, type {@code climate-sensor}: air temperature (input {@code temperature}, °C) and
 * relative humidity (input {@code humidity}, %) as one record on output {@code climate}
 * ({@code temperatureC}, {@code humidityPct}; a field appears once its sensor has read). Readings outside what
 * room sensors measure (−40..85 °C, 0..100 %) are dropped and counted. Either input may be left unwired.
 */
public final class ClimateSensor extends SensorActuatorMethod {

    private static final InputPort<NumberValue> TEMPERATURE = InputPort.optional("temperature", NumberValue.class,
            Delivery.latest());
    private static final InputPort<NumberValue> HUMIDITY = InputPort.optional("humidity", NumberValue.class,
            Delivery.latest());
    private static final OutputPort<RecordValue> CLIMATE = OutputPort.of("climate", RecordValue.class,
            Shape.record("air temperature (°C) and relative humidity (%)", Climate.LAYOUT));
    static final Ports PORTS = Ports.of(TEMPERATURE, HUMIDITY, CLIMATE);

    private final Output<RecordValue> climate = output(CLIMATE);
    private Double temperatureC;
    private Double humidityPct;
    private long dropped;

    ClimateSensor() {
        input(TEMPERATURE, this::onTemperature);
        input(HUMIDITY, this::onHumidity);
    }

    private void onTemperature(NumberValue value, Sample sample) {
        if (accept(value.value(), -40, 85, "°C")) {
            temperatureC = value.value();
            publish();
        }
    }

    private void onHumidity(NumberValue value, Sample sample) {
        if (accept(value.value(), 0, 100, "%")) {
            humidityPct = value.value();
            publish();
        }
    }

    private boolean accept(double v, double min, double max, String unit) {
        if (v >= min && v <= max) {
            return true;
        }
        if (dropped++ == 0) {
            log().warn("{}: a reading of {} {} is out of {}..{}; dropped (further ones only counted)", id(), v, unit,
                    min, max);
        }
        return false;
    }

    private void publish() {
        emit(climate, RecordValue.of(new Climate(temperatureC, humidityPct)));
    }

    /** Readings dropped since start. */
    public long dropped() {
        return dropped;
    }

    /** Makes {@code climate-sensor} methods. */
    public static final class Provider extends SimpleMethodProvider<NoParams> {
        public Provider() {
            super("climate-sensor", "Air temperature and relative humidity as one record", NoParams.class,
                    PORTS, (layer, p) -> new ClimateSensor(), Layer.SENSORS_ACTUATORS);
        }
    }
}
