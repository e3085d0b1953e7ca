package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class RoomSensorsTest {

    @Test
    void lightReadingsAreCheckedClippedAndSmoothed() {
        LightSensor sensor = new LightSensor(ParamsJson.of(LightSensor.Params.class, "{\"maxLux\": 1000.0, \"smoothing\": 0.5}"));
        MethodHarness h = MethodHarness.started("light", sensor);
        h.push("lux", new NumberValue(100)).push("lux", new NumberValue(-3)).push("lux", new NumberValue(5000));
        assertThat(h.values("lux")).containsExactly(new NumberValue(100), new NumberValue(550));
        assertThat(sensor.dropped()).isEqualTo(1);
    }

    @Test
    void climateJoinsTemperatureAndHumidityAndDropsImpossibleReadings() {
        MethodHarness h = MethodHarness.started("climate", new ClimateSensor());
        h.push("temperature", new NumberValue(21.5)).push("humidity", new NumberValue(140))
                .push("humidity", new NumberValue(40));
        assertThat(h.values("climate")).containsExactly(RecordValue.builder().put("temperatureC", 21.5).build(),
                RecordValue.builder().put("temperatureC", 21.5).put("humidityPct", 40.0).build());
    }

    @Test
    void theSoundLevelOfAFullScaleSineIsAboutMinusThreeDbAndSilenceIsTheFloor() {
        int n = 1600;
        ByteBuffer pcm = ByteBuffer.allocate(n * 2).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < n; i++) {
            pcm.putShort((short) Math.round(32767 * Math.sin(2 * Math.PI * 440 * i / 16000.0)));
        }
        MethodHarness h = MethodHarness.started("sound", new SoundLevel(ParamsJson.of(SoundLevel.Params.class, "{\"floorDb\": -90.0}")));
        h.push("audio", AudioChunk.of(AudioFormat.MONO_16K, pcm.array()));
        h.push("audio", AudioChunk.of(AudioFormat.MONO_16K, new byte[320]));
        assertThat(((NumberValue) h.values("levelDb").get(0)).value()).isCloseTo(-3.01, within(0.05));
        assertThat(h.values("levelDb").get(1)).isEqualTo(new NumberValue(-90));
    }

    @Test
    void blindsSendAPositionInPercentAndTheSpeakerTheTextToSay() {
        MethodHarness blinds = MethodHarness.started("blinds", new Blinds(ParamsJson.of(Blinds.Params.class, "{\"invert\": true}")));
        blinds.push("open", new NumberValue(0.25)).push("open", new NumberValue(0.25));
        assertThat(blinds.values("command")).containsExactly(RecordValue.builder().put("position", 75).build());
        MethodHarness speaker = MethodHarness.started("speaker", new RoomSpeaker(ParamsJson.of(RoomSpeaker.Params.class, "{\"volume\": 30, \"maxLength\": 5}")));
        speaker.push("text", new TextValue("  hello there ")).push("text", new TextValue("   "));
        assertThat(speaker.values("command")).containsExactly(
                RecordValue.builder().put("say", "hello").put("volume", 30).build());
    }

    @Test
    void theBlindsAndSpeakerCommandsAreTheJsonTheDevicesTake() {
        MethodHarness blinds = MethodHarness.started("blinds", new Blinds(ParamsJson.of(Blinds.Params.class, "{}")));
        blinds.push("open", new NumberValue(0.42));
        assertThat(((RecordValue) blinds.last("command")).jsonView().toString()).isEqualTo("{\"position\":42}");
        assertThat(((RecordValue) blinds.last("command")).form(CoverCommand.class)).contains(new CoverCommand(42));
        MethodHarness speaker = MethodHarness.started("speaker", new RoomSpeaker(ParamsJson.of(RoomSpeaker.Params.class, "{}")));
        speaker.push("text", new TextValue("dinner is ready"));
        assertThat(((RecordValue) speaker.last("command")).jsonView().toString())
                .isEqualTo("{\"say\":\"dinner is ready\",\"volume\":50}");
        assertThat(((RecordValue) speaker.last("command")).form(SpeakerCommand.class))
                .contains(new SpeakerCommand("dinner is ready", 50));
    }
}
