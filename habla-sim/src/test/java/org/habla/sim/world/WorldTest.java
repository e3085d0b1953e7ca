package org.habla.sim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class WorldTest {

    private final World room = World.builtIn("pioneer-room");

    @Test
    void theShippedWorldsLoadWithTheContractSizes() {
        assertThat(room.walls()).hasSize(4);
        assertThat(room.target().radiusM()).isEqualTo(0.15);
        assertThat(room.rangeAlong(3, 3, 0, 10)).isCloseTo(3.0, within(1e-9));
        World arena = World.builtIn("aibo-arena");
        assertThat(arena.target().radiusM()).isEqualTo(0.05);
        assertThat(arena.target().color()).isEqualTo("pink");
        assertThat(arena.rangeAlong(1.25, 0.3, Math.PI / 2, 10)).isLessThan(2.5);
        assertThat(arena.teacher().phrases().get("left")).isEqualTo("turn left");
        assertThat(room.teacher().notes().get("back")).isEqualTo("C6");
    }

    @Test
    void fromTheRoomsStartPoseTheObjectIsTheNearestThingByAMetre() {
        // On the Pioneer, distance_angle is the nearest sonar echo: from the default start it must be the object.
        Pose2 start = room.robotStart();
        Target t = room.target();
        double toObject = t.surfaceDistance(start.xM(), start.yM());
        double toWalls = room.walls().stream().mapToDouble(w -> w.distanceTo(start.xM(), start.yM())).min().orElseThrow();

        assertThat(room.clearance(start.xM(), start.yM(), t)).isEqualTo(toObject);
        assertThat(toWalls - toObject).isGreaterThan(1.0);
        assertThat(room.directionToNearest(start.xM(), start.yM(), t))
                .isCloseTo(Math.atan2(t.yM() - start.yM(), t.xM() - start.xM()), within(1e-9));
    }

    @Test
    void aRayStopsAtTheNearestWallOrTheTargetAndIsCappedAtMaxRange() {
        // Towards the west wall from (1.5, 1.5): 1.5 m.
        assertThat(room.rangeAlong(1.5, 1.5, Math.PI, 5)).isCloseTo(1.5, within(1e-9));
        // Diagonally into the corner (0, 0).
        assertThat(room.rangeAlong(1.5, 1.5, -3 * Math.PI / 4, 5)).isCloseTo(Math.hypot(1.5, 1.5), within(1e-9));
        // Straight at the target: distance to its edge.
        Target t = room.target();
        double angle = Math.atan2(t.yM() - 1.5, t.xM() - 1.5);
        double expected = Math.hypot(t.xM() - 1.5, t.yM() - 1.5) - t.radiusM();
        assertThat(room.rangeAlong(1.5, 1.5, angle, 10)).isCloseTo(expected, within(1e-9));
        // Capped.
        assertThat(room.rangeAlong(1.5, 1.5, 0, 2)).isEqualTo(2);
        // A target moved elsewhere no longer shadows the ray.
        assertThat(room.rangeAlong(1.5, 1.5, angle, 10, t.movedTo(1, 5))).isGreaterThan(expected + 1);
    }

    @Test
    void aRoundRobotCollidesWithWallsAndTheTarget() {
        Target t = room.target();
        assertThat(room.collides(0.2, 3, 0.25, t)).isTrue();
        assertThat(room.collides(0.3, 3, 0.25, t)).isFalse();
        assertThat(room.collides(t.xM() - 0.35, t.yM(), 0.25, t)).isTrue();
        assertThat(room.collides(t.xM() - 0.45, t.yM(), 0.25, t)).isFalse();
        assertThat(room.clearance(3, 3, t)).isCloseTo(Math.min(3, t.surfaceDistance(3, 3)), within(1e-9));
    }

    @Test
    void aWorldFileWithATypoIsRejectedNamingThePath() {
        assertThatThrownBy(() -> read("{\"name\":\"x\",\"arena\":{\"walls\":[]},\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":0.1},"
                + "\"robot\":{\"xM\":0,\"yM\":0,\"thetaRad\":0},\"teacher\":{\"comandEveryS\":2}}"))
                .isInstanceOf(IOException.class).hasMessageContaining("$.teacher.comandEveryS");
        assertThatThrownBy(() -> read("{\"name\":\"x\",\"arena\":{\"walls\":[[0,0,1]]},\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":0.1},"
                + "\"robot\":{\"xM\":0,\"yM\":0}}"))
                .isInstanceOf(IOException.class).hasMessageContaining("$.arena.walls[0]");
        assertThatThrownBy(() -> read("{\"name\":\"x\",\"arena\":{\"walls\":[]},\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":-1},"
                + "\"robot\":{\"xM\":0,\"yM\":0}}"))
                .isInstanceOf(IOException.class).hasMessageContaining("radiusM");
        assertThatThrownBy(() -> read("{\"name\":\"x\",\"arena\":{\"walls\":[]},\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":1},"
                + "\"robot\":{\"yM\":0}}"))
                .isInstanceOf(IOException.class).hasMessageContaining("$.robot.xM is missing");
        assertThatThrownBy(() -> read("{\"name\": "))
                .isInstanceOf(IOException.class).hasMessageContaining("not valid JSON");
        assertThatThrownBy(() -> World.builtIn("no-such-world")).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void theTeacherDefaultsApplyWhenAWorldFileOmitsThem() throws IOException {
        World w = read("{\"name\":\"x\",\"arena\":{\"walls\":[]},\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":0.1},"
                + "\"robot\":{\"xM\":0,\"yM\":0},\"teacher\":{\"present\":false}}");
        assertThat(w.teacher().present()).isFalse();
        assertThat(w.teacher().commandEveryS()).isEqualTo(3.0);
        assertThat(w.teacher().judgeAfterS()).isEqualTo(1.5);
        assertThat(w.teacher().notes()).isEqualTo(TeacherSettings.DEFAULTS.notes());
    }

    private static World read(String json) throws IOException {
        return WorldReader.read(new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "test.json");
    }
}
