package org.habla.methods;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.methods.actuators.Wheels;
import org.habla.methods.actuators.WheelsParams;
import org.habla.methods.sensors.Buttons;
import org.habla.methods.sensors.ButtonsParams;
import org.habla.methods.sensors.Camera;
import org.habla.methods.sensors.CameraParams;
import org.habla.methods.sensors.Head;
import org.habla.methods.sensors.HeadParams;
import org.habla.methods.sensors.Keyboard;
import org.habla.methods.sensors.KeyboardParams;
import org.habla.methods.sensors.Legs;
import org.habla.methods.sensors.LegsParams;
import org.habla.methods.sensors.Microphone;
import org.habla.methods.sensors.MicrophoneParams;
import org.habla.methods.sensors.Odometry;
import org.habla.methods.sensors.OdometryParams;
import org.habla.methods.sensors.RangeSensor;
import org.habla.methods.sensors.RangeSensorParams;
import org.habla.methods.sensors.Speaker;
import org.habla.methods.sensors.SpeakerParams;
import org.habla.methods.voice.Speech;
import org.habla.methods.voice.SpeechParams;
import org.habla.plugin.MethodProvider;
import org.junit.jupiter.api.Test;

/**
 * The sensor, actuator and voice types list their ports without making a method, and the methods they make
 * bind exactly those ports.
 */
class PortsListedBTest {

    /** The ports {@code provider} lists for {@code params}, once a method made from them was checked against them. */
    private static <P extends Record> Ports made(MethodProvider<P> provider, Record params) {
        Layer layer = provider.layers().iterator().next();
        assertThat(MethodProvider.make(provider, layer, params).layer()).isEqualTo(layer);
        return provider.ports(layer, provider.paramsType().cast(params));
    }

    private static void lists(MethodProvider<?> provider, Record params, List<String> inputs, List<String> outputs) {
        Ports ports = made(provider, params);
        assertThat(ports.inputs()).as(provider.name() + " inputs").extracting(InputPort::name)
                .containsExactlyInAnyOrderElementsOf(inputs);
        assertThat(ports.outputs()).as(provider.name() + " outputs").extracting(OutputPort::name)
                .containsExactlyInAnyOrderElementsOf(outputs);
    }

    private static InputPort<?> input(MethodProvider<?> provider, Record params, String name) {
        return made(provider, params).input(name).orElseThrow();
    }

    @Test
    void everyTypeMakesAMethodThatBindsThePortsItListsForDefaultParams() {
        lists(new Buttons.Provider(), ButtonsParams.defaults(), List.of("buttons"), List.of("pressed", "touch"));
        lists(new Camera.Provider(), CameraParams.defaults(), List.of("image"), List.of("image", "camera"));
        lists(new Head.Provider(), HeadParams.defaults(), List.of("pose", "command"), List.of("pose", "head"));
        lists(new Keyboard.Provider(), KeyboardParams.defaults(), List.of("line"), List.of("line"));
        lists(new Legs.Provider(), LegsParams.defaults(), List.of("walk"), List.of("walk"));
        lists(new Microphone.Provider(), MicrophoneParams.defaults(), List.of("audio"), List.of("audio"));
        lists(new Odometry.Provider(), OdometryParams.defaults(), List.of("odometry"), List.of("pose", "velocity"));
        lists(new RangeSensor.SonarProvider(), RangeSensorParams.defaults(), List.of("ranges", "head"),
                List.of("ranges", "scan"));
        lists(new RangeSensor.InfraredProvider(), RangeSensorParams.defaults(), List.of("ranges", "head"),
                List.of("ranges", "scan"));
        lists(new RangeSensor.LaserProvider(), RangeSensorParams.defaults(), List.of("ranges", "head"),
                List.of("ranges", "scan"));
        lists(new Speaker.Provider(), SpeakerParams.defaults(), List.of("audio", "text"), List.of("speaker"));
        lists(new Wheels.Provider(), WheelsParams.defaults(), List.of("motion"), List.of("motion", "limits"));
        lists(new Speech.Provider(), SpeechParams.defaults(), List.of("text", "emotion"), List.of("audio"));
    }

    @Test
    void theQueueParamSetsTheDeliveryOfTheInputItSizes() {
        assertThat(input(new Legs.Provider(), LegsParams.defaults(), "walk").delivery()).isEqualTo(Delivery.queue(8));
        assertThat(input(new Legs.Provider(), ParamsJson.of(LegsParams.class, "{\"queue\": 3}"), "walk").delivery())
                .isEqualTo(Delivery.queue(3));

        assertThat(input(new Microphone.Provider(), MicrophoneParams.defaults(), "audio").delivery())
                .isEqualTo(Delivery.queue(64));
        assertThat(input(new Microphone.Provider(),
                ParamsJson.of(MicrophoneParams.class, "{\"queue\": 5}"), "audio").delivery())
                .isEqualTo(Delivery.queue(5));

        assertThat(input(new Speaker.Provider(), SpeakerParams.defaults(), "audio").delivery())
                .isEqualTo(Delivery.queue(64));
        InputPort<?> audio = input(new Speaker.Provider(), ParamsJson.of(SpeakerParams.class, "{\"queue\": 7}"), "audio");
        assertThat(audio.delivery()).isEqualTo(Delivery.queue(7));
        assertThat(audio.optional()).isTrue();
    }
}
