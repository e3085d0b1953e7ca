package org.habla.sim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class BodyTest {

    private static final double DT = 0.01;
    private final World room = World.builtIn("pioneer-room");
    private final Body.Limits limits = new Body.Limits(0.25, 0.5, 2.0, 0.3, 1.0);

    @Test
    void speedRampsUpWithinTheAccelerationLimit() {
        Body body = new Body(limits, new Pose2(1, 3, 0));
        body.command(0.4, 0, 0);
        run(body, 0.5);
        assertThat(body.forwardMps()).isCloseTo(0.15, within(1e-6));
        run(body, 1.0);
        assertThat(body.forwardMps()).isCloseTo(0.4, within(1e-9));
        // Distance while ramping: 0.4²/(2·0.3) ≈ 0.267 m over the first 1.333 s, then 0.4 m/s.
        double expected = 0.4 * 0.4 / (2 * 0.3) + 0.4 * (1.5 - 0.4 / 0.3);
        assertThat(body.pose().xM() - 1).isCloseTo(expected, within(0.01));
        assertThat(body.pose().yM()).isCloseTo(3, within(1e-9));
    }

    @Test
    void slowingDownUsesTheDecelerationLimit() {
        Body body = new Body(new Body.Limits(0.25, 0.5, 2.0, 0.3, 1.0, 0.6, 2.0), new Pose2(1, 3, 0));
        body.command(0.3, 0, 0);
        run(body, 1.0);
        assertThat(body.forwardMps()).isCloseTo(0.3, within(1e-9));
        body.command(0, 0, 0);
        run(body, 0.25);
        assertThat(body.forwardMps()).isCloseTo(0.15, within(1e-6));
        body.command(-0.3, 0, 0);
        run(body, 0.25);
        assertThat(body.forwardMps()).as("through zero at the deceleration rate").isCloseTo(0.0, within(1e-6));
    }

    @Test
    void aCommandAboveTheMaximumIsClamped() {
        Body body = new Body(limits, new Pose2(3, 3, 0));
        body.command(5, 0, -9);
        run(body, 5);
        assertThat(body.forwardMps()).isEqualTo(0.5);
        assertThat(body.turnRadps()).isEqualTo(-2.0);
    }

    @Test
    void drivingIntoAWallStallsTheBodyThatThenTurnsAndBacksAway() {
        Body body = new Body(limits, new Pose2(5, 1, 0));
        body.command(0.5, 0, 0);
        run(body, 6);
        assertThat(body.stalled()).isTrue();
        assertThat(body.pose().xM()).isCloseTo(6 - 0.25, within(0.001));
        assertThat(body.forwardMps()).isZero();
        assertThat(body.contactBearingRad()).isCloseTo(0, within(1e-6));
        for (int i = 0; i < 100; i++) {
            body.step(DT, room, room.target());
            assertThat(body.stalled()).as("still pushing at step %d", i).isTrue();
        }
        body.command(0, 0, 1);
        run(body, 0.5);
        assertThat(body.pose().thetaRad()).isGreaterThan(0.1);
        body.command(-0.3, 0, 0);
        run(body, 2);
        assertThat(body.stalled()).isFalse();
        assertThat(body.pose().xM()).isLessThan(5.6);
        assertThat(body.contactBearingRad()).isNaN();
    }

    @Test
    void theTargetBlocksTheBodyLikeAWall() {
        Target t = room.target();
        Body body = new Body(limits, new Pose2(t.xM() - 1, t.yM(), 0));
        body.command(0.5, 0, 0);
        for (int i = 0; i < 400; i++) {
            body.step(DT, room, t);
        }
        assertThat(body.stalled()).isTrue();
        assertThat(t.surfaceDistance(body.pose().xM(), body.pose().yM())).isCloseTo(0.25, within(0.001));
    }

    @Test
    void turningFollowsTheCommandedRate() {
        Body body = new Body(new Body.Limits(0.25, 0.5, 2.0, 0.3, 100), new Pose2(3, 3, 0));
        body.command(0, 0, 0.5);
        run(body, 1);
        assertThat(body.pose().thetaRad()).isCloseTo(0.5, within(0.01));
        assertThat(body.pose().xM()).isCloseTo(3, within(1e-9));
    }

    private void run(Body body, double seconds) {
        for (int i = 0; i < Math.round(seconds / DT); i++) {
            body.step(DT, room, room.target());
        }
    }
}
