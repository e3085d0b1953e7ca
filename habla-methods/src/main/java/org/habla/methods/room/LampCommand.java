package org.habla.methods.room;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code command} record of {@code lamp}: what a smart lamp is told, in the Zigbee2MQTT and Home Assistant JSON
 * light schema: {@code {"state": "ON", "brightness": 127}} for a lamp that dims, {@code {"state": "ON"}} for one
 * that does not, {@code {"state": "OFF"}}.
 *
 * @param on         whether the lamp is to be on
 * @param brightness the device's brightness, 1 up to the lamp's maxBrightness; null when off or when the lamp does
 *                   not dim
 */
public record LampCommand(boolean on, Integer brightness) implements RecordForm {

    /** The fields of a lamp command. */
    public static final RecordLayout<LampCommand> LAYOUT = RecordLayout.of(LampCommand.class)
            .text("state", c -> c.on ? "ON" : "OFF").doc("ON or OFF")
            .optionalLongInteger("brightness", c -> c.brightness == null ? null : c.brightness.longValue())
            .doc("the device's brightness, up to the lamp's maxBrightness (Zigbee: 254); absent when off or when the "
                    + "lamp does not dim")
            .build();

    /** Off. */
    public static final LampCommand OFF = new LampCommand(false, null);

    /** On, for a lamp that does not dim. */
    public static final LampCommand ON = new LampCommand(true, null);

    public LampCommand {
        if (brightness != null && (!on || brightness < 1)) {
            throw new IllegalArgumentException("only a lamp that is on has a brightness, of 1 or more; was "
                    + (on ? "on" : "off") + " at " + brightness);
        }
    }

    /** On, at {@code brightness} (1 or more). */
    public static LampCommand dimmedTo(int brightness) {
        return new LampCommand(true, brightness);
    }

    @Override
    public RecordLayout<LampCommand> layout() {
        return LAYOUT;
    }
}
