package org.habla.drivers.mqtt;

import java.util.Set;
import org.habla.bridge.Bridge;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.BridgeProvider;

/** Makes bridges of type {@code mqtt}: exposed methods on an MQTT broker, with Home Assistant discovery. */
public final class MqttBridgeProvider implements BridgeProvider<MqttBridgeParams> {

    @Override
    public String name() {
        return "mqtt";
    }

    @Override
    public String description() {
        return "Exposed methods on an MQTT 5 broker: samples as JSON on <baseTopic>/<system>/<socket>, actions from "
                + "<baseTopic>/<system>/<socket>/set for the sockets listed in actions, Home Assistant discovery";
    }

    @Override
    public Class<MqttBridgeParams> paramsType() {
        return MqttBridgeParams.class;
    }

    @Override
    public Set<String> socketsNamed(MqttBridgeParams params) {
        return params.sockets();
    }

    @Override
    public Set<String> actionSockets(MqttBridgeParams params) {
        return Set.copyOf(params.actions());
    }

    @Override
    public Bridge create(InterfaceAddress address, MqttBridgeParams params) {
        return new MqttBridge(address, params);
    }
}
