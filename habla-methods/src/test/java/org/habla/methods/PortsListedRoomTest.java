package org.habla.methods;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.methods.room.Blinds;
import org.habla.methods.room.ClimateSensor;
import org.habla.methods.room.Comfort;
import org.habla.methods.room.Lamp;
import org.habla.methods.room.LightLevels;
import org.habla.methods.room.LightSensor;
import org.habla.methods.room.Occupancy;
import org.habla.methods.room.Presence;
import org.habla.methods.room.RoomAction;
import org.habla.methods.room.RoomSpeaker;
import org.habla.methods.room.SoundLevel;
import org.habla.methods.virtual.Action;
import org.habla.methods.virtual.ActionParams;
import org.habla.methods.virtual.Command;
import org.habla.methods.virtual.CommandParams;
import org.habla.methods.virtual.DistanceAngle;
import org.habla.methods.virtual.DistanceAngleParams;
import org.habla.methods.virtual.LinkState;
import org.habla.methods.virtual.LinkStateParams;
import org.habla.methods.virtual.Reward;
import org.habla.methods.virtual.RewardParams;
import org.habla.methods.virtual.RobotPose;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.NoParams;
import org.junit.jupiter.api.Test;

/** The room and virtual method types list their ports without making a method, and make methods that bind them. */
class PortsListedRoomTest {

    @Test
    void roomTypesListTheirPortsWithDefaultParams() {
        assertListed(new Blinds.Provider(), ParamsJson.of(Blinds.Params.class, "{}"), List.of("open"), List.of("command"));
        assertListed(new ClimateSensor.Provider(), new NoParams(), List.of("temperature", "humidity"),
                List.of("climate"));
        assertListed(new Comfort.Provider(), ParamsJson.of(Comfort.Params.class, "{}"),
                List.of("climate", "lux", "sound"), List.of("comfort"));
        assertListed(new Lamp.Provider(), ParamsJson.of(Lamp.Params.class, "{}"), List.of("level", "state"),
                List.of("command", "level", "reported"));
        assertListed(new LightSensor.Provider(), ParamsJson.of(LightSensor.Params.class, "{}"), List.of("lux"), List.of("lux"));
        assertListed(new Presence.Provider(), ParamsJson.of(Presence.Params.class, "{}"), List.of("motion", "door"),
                List.of("present"));
        assertListed(new RoomSpeaker.Provider(), ParamsJson.of(RoomSpeaker.Params.class, "{}"), List.of("text"),
                List.of("command"));
        assertListed(new SoundLevel.Provider(), ParamsJson.of(SoundLevel.Params.class, "{}"), List.of("audio", "level"),
                List.of("levelDb"));
    }

    @Test
    void virtualTypesListTheirPortsWithDefaultParams() {
        assertListed(new Action.Provider(), ActionParams.defaults(), List.of("action"), List.of("motion", "action"));
        assertListed(new Command.Provider(), CommandParams.defaults(), List.of("in"), List.of("command"));
        assertListed(new DistanceAngle.Provider(), DistanceAngleParams.defaults(), List.of("nearest", "position"),
                List.of("distance_angle"));
        assertListed(new LinkState.Provider(), LinkStateParams.defaults(), List.of("link"), List.of("link"));
        assertListed(new Reward.Provider(), RewardParams.defaults(), List.of("text", "buttons"), List.of("reward"));
        assertListed(new RobotPose.Provider(), new NoParams(), List.of("pose"), List.of("pose"));
    }

    @Test
    void everyZoneIsAnInputOfOccupancyAndLightLevels() {
        List<String> one = List.of("desk");
        List<String> three = List.of("desk", "sofa", "kitchen");
        assertListed(new Occupancy.Provider(), ParamsJson.of(Occupancy.Params.class, "{\"zones\": [\"desk\"]}"), one, List.of("occupancy"));
        assertListed(new Occupancy.Provider(), new Occupancy.Params(three, 0), three, List.of("occupancy"));
        assertListed(new LightLevels.Provider(), ParamsJson.of(LightLevels.Params.class, "{\"zones\": [\"desk\"]}"), one, List.of("light"));
        assertListed(new LightLevels.Provider(), new LightLevels.Params(three, 150.0), three, List.of("light"));
    }

    @Test
    void aRoomHasAnOutputPerLampAndBlindsAndOneForItsSpeaker() {
        assertListed(new RoomAction.Provider(), ParamsJson.of(RoomAction.Params.class, "{\"lamps\": [\"desk\"]}"), List.of("action"),
                List.of("action", "lamps", "desk"));
        assertListed(new RoomAction.Provider(), ParamsJson.of(RoomAction.Params.class, "{\"lamps\": [\"desk\", \"sofa\"], \"blinds\": [\"window\"], \"speaker\": true}"),
                List.of("action"), List.of("action", "lamps", "desk", "sofa", "window", "say"));
    }

    /** {@code provider} lists these inputs and outputs for {@code params}, and makes a method that binds them. */
    private static <P extends Record> void assertListed(MethodProvider<P> provider, P params, List<String> inputs,
            List<String> outputs) {
        for (Layer layer : provider.layers()) {
            assertThat(MethodProvider.make(provider, layer, params).layer()).isEqualTo(layer);
            Ports ports = provider.ports(layer, params);
            assertThat(ports.inputs().stream().map(InputPort::name).toList()).as(provider.name() + " inputs")
                    .containsExactlyInAnyOrderElementsOf(inputs);
            assertThat(ports.outputs().stream().map(OutputPort::name).toList()).as(provider.name() + " outputs")
                    .containsExactlyInAnyOrderElementsOf(outputs);
        }
    }
}
