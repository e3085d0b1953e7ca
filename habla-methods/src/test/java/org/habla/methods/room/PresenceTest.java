package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.junit.jupiter.api.Test;

class PresenceTest {

    private static final NumberValue ON = new NumberValue(1);
    private static final NumberValue OFF = new NumberValue(0);

    private static MethodHarness presence(int holdMs, int doorHoldMs) {
        return MethodHarness.started("presence", new Presence(new Presence.Params(holdMs, doorHoldMs)));
    }

    @Test
    void motionMakesTheZoneOccupiedAndTheHoldOutlastsAQuietSensor() {
        MethodHarness h = presence(5_000, 1_000);
        h.push("motion", ON);
        assertThat(h.values("present")).containsExactly(ON);
        h.push("motion", OFF).advanceMillis(4_800);
        assertThat(h.values("present")).as("still held").containsExactly(ON);
        h.advanceMillis(300);
        assertThat(h.values("present")).containsExactly(ON, OFF);
    }

    @Test
    void newMotionDuringTheHoldStartsItAgain() {
        MethodHarness h = presence(5_000, 1_000);
        h.push("motion", ON).push("motion", OFF).advanceMillis(4_000);
        h.push("motion", ON).push("motion", OFF).advanceMillis(4_000);
        assertThat(h.values("present")).containsExactly(ON);
        h.advanceMillis(1_200);
        assertThat(h.last("present")).isEqualTo(OFF);
    }

    @Test
    void aDoorThatOpensOrClosesMeansSomeonePassedForTheDoorHold() {
        MethodHarness h = presence(5_000, 2_000);
        h.push("door", new NumberValue(0));
        assertThat(h.values("present")).as("a door at rest says nobody").containsExactly(OFF);
        h.push("door", new NumberValue(1));
        assertThat(h.last("present")).isEqualTo(ON);
        h.advanceMillis(2_200);
        assertThat(h.values("present")).containsExactly(OFF, ON, OFF);
        h.push("door", new NumberValue(1));
        assertThat(h.values("present")).as("no change, no passage").hasSize(3);
    }
}
