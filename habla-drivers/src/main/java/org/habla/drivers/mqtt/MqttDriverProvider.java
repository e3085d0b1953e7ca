package org.habla.drivers.mqtt;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** Makes drivers of type {@code mqtt}: devices on an MQTT broker (Zigbee2MQTT, Tasmota, ESPHome, Home Assistant). */
public final class MqttDriverProvider implements DriverProvider<MqttParams> {

    @Override
    public String name() {
        return "mqtt";
    }

    @Override
    public String description() {
        return "Devices on an MQTT broker (3.1.1 or 5, TLS, user name and password; default port 1883): topics "
                + "mapped to reading channels, command channels published (never retained), availability as staleness";
    }

    @Override
    public Class<MqttParams> paramsType() {
        return MqttParams.class;
    }

    @Override
    public Driver create(InterfaceAddress address, MqttParams params) {
        return new MqttDriver(address, params);
    }
}
