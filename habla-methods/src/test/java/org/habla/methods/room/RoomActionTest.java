package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class RoomActionTest {

    private static MethodHarness room() {
        return MethodHarness.started("room", new RoomAction(new RoomAction.Params(List.of("desk", "sofa"),
                List.of("window"), true)));
    }

    @Test
    void lampActionsSetTheirOwnOutputAndTheLampsRecord() {
        MethodHarness h = room();
        h.write("action", new TextValue("Desk  ON")).write("action", new TextValue("sofa 0.25"));
        assertThat(h.values("desk")).containsExactly(new NumberValue(1));
        assertThat(h.values("sofa")).containsExactly(new NumberValue(0.25));
        assertThat(h.last("lamps")).isEqualTo(RecordValue.builder().put("desk", 1.0).put("sofa", 0.25).build());
        assertThat(h.values("action")).containsExactly(new TextValue("desk on"), new TextValue("sofa 0.25"));
        h.write("action", new TextValue("all off"));
        assertThat(h.last("desk")).isEqualTo(new NumberValue(0));
        assertThat(h.last("sofa")).isEqualTo(new NumberValue(0));
    }

    @Test
    void blindsAndTheSpeakerHaveTheirOutputs() {
        MethodHarness h = room();
        h.write("action", new TextValue("window close")).write("action", new TextValue("say Good morning"));
        assertThat(h.values("window")).containsExactly(new NumberValue(0));
        assertThat(h.values("say")).containsExactly(new TextValue("Good morning"));
        assertThat(h.values("lamps")).as("no lamp changed").isEmpty();
    }

    @Test
    void aClientsUnknownActionIsRefusedNamingTheTargets() {
        MethodHarness h = room();
        for (String bad : new String[] {"kitchen on", "desk 1.5", "desk", "window on", ""}) {
            assertThatThrownBy(() -> h.write("action", new TextValue(bad))).hasMessageContaining("desk, sofa")
                    .hasMessageContaining("window");
        }
        assertThat(h.values("action")).isEmpty();
    }

    @Test
    void namesThatWouldClashWithItsOwnOutputsAreRefused() {
        assertThatThrownBy(() -> new RoomAction.Params(List.of("lamps"), List.of(), false))
                .hasMessageContaining("'lamps' cannot name a lamp");
        assertThatThrownBy(() -> new RoomAction.Params(List.of("desk"), List.of("desk"), false))
                .hasMessageContaining("named twice");
    }
}
