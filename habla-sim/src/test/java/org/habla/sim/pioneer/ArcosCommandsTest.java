package org.habla.sim.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import org.habla.drivers.pioneer.StandardSip;
import org.habla.sim.world.World;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The simulated controller's commands, sent as hand-made packets and seen in its SIPs. */
class ArcosCommandsTest {

    private PioneerSim sim;
    private RawArcosClient client;

    @BeforeEach
    void start() throws IOException {
        // Slow enough that these PULSE-less exchanges stay well inside the 2 s watchdog.
        sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 4));
        client = new RawArcosClient(sim.arcosPort());
    }

    @AfterEach
    void stop() throws IOException {
        client.close();
        sim.close();
    }

    @Test
    void theHandshakeEchoesTheSyncsAndNamesTheRobot() throws IOException {
        client.send("00");
        assertThat(client.next()).containsExactly(0);
        client.send("01");
        assertThat(client.next()).containsExactly(1);
        client.send("02");
        byte[] reply = client.next();
        assertThat(reply[0]).isEqualTo((byte) 2);
        assertThat(new String(reply, 1, reply.length - 1, StandardCharsets.ISO_8859_1))
                .isEqualTo("HABLA-sim\0Pioneer\0p2dx\0");
        client.send("01");
        StandardSip first = client.sip(s -> true, 5);
        assertThat(first.motorsEnabled()).as("motors stay off until ENABLE").isFalse();
        assertThat(first.flags() & 0x1E).as("sonar on").isEqualTo(0x1E);
    }

    @Test
    void withMotorsDisabledVelocityCommandsAreIgnored() throws IOException {
        client.connect();
        client.send(11, 300);
        client.send(21, 20);
        for (int i = 0; i < 10; i++) {
            StandardSip sip = client.sip(s -> true, 5);
            assertThat(sip.leftVel()).isZero();
            assertThat(sip.rightVel()).isZero();
        }
    }

    @Test
    void vel2DrivesTheWheelsIndependentlyAndSetoResetsTheOdometry() throws IOException {
        client.connect();
        client.send(4, 1);
        // Left 5 × 20 = 100 mm/s, right 10 × 20 = 200 mm/s: high byte left, low byte right.
        client.send(32, (5 << 8) | 10);
        StandardSip sip = client.sip(s -> s.leftVel() == 100 && s.rightVel() == 200, 100);
        assertThat(sip.rotVelDdegps().getAsInt() / 10.0)
                .isCloseTo(Math.toDegrees(50 * P2dx.DIFF_CONV), within(0.2));
        assertThat(sip.moving()).isTrue();
        // Backwards on the left wheel: the packed value is negative and travels as 0x1B + magnitude.
        client.send(32, (short) ((-5 << 8) | 5));
        client.sip(s -> s.leftVel() == -100 && s.rightVel() == 100, 100);
        client.send("1D"); // STOP
        StandardSip still = client.sip(s -> s.leftVel() == 0 && s.rightVel() == 0, 100);
        assertThat(still.moving()).isFalse();
        assertThat(still.xPos()).isPositive();
        client.send("07"); // SETO
        StandardSip reset = client.sip(s -> s.xPos() == 0 && s.yPos() == 0, 100);
        assertThat(reset.thPos()).isZero();
    }

    @Test
    void eStopHaltsAtOnceWhereStopRampsDown() throws IOException {
        client.connect();
        client.send(4, 1);
        client.send(11, 400);
        client.sip(s -> s.leftVel() == 400, 100);
        client.send("1D"); // STOP: brakes at 0.6 m/s², 60 mm/s per SIP period
        // The reader may lag the stream: the first SIP that shows a change is the one to judge.
        StandardSip braking = client.sip(s -> s.leftVel() < 400, 100);
        assertThat(braking.leftVel()).isBetween(300, 399);
        client.send(11, 400);
        client.sip(s -> s.leftVel() == 400, 100);
        client.send("37"); // E_STOP: the first SIP that shows it shows the robot still
        assertThat(client.sip(s -> s.leftVel() < 400, 100).leftVel()).isZero();
    }

    @Test
    void closeStopsTheSipsAndAnotherHandshakeReopens() throws IOException {
        client.connect();
        client.sip(s -> true, 5);
        client.send("02"); // CLOSE
        client.timeout(1_000); // 4 s of sim time
        // Drain what was in flight, then silence.
        int afterClose = 0;
        try {
            while (afterClose < 10) {
                client.next();
                afterClose++;
            }
        } catch (SocketTimeoutException expected) {
            // no more SIPs
        }
        assertThat(afterClose).isLessThan(3);
        client.timeout(5_000);
        client.connect();
        assertThat(client.sip(s -> true, 5)).isNotNull();
    }

    @Test
    void speedSetPointsOutliveCloseAndDriveAgainOnceTheMotorsAreEnabledUnlessStoppedFirst() throws IOException {
        client.connect();
        client.send(4, 1);
        client.send(11, 300);
        client.sip(s -> s.leftVel() == 300, 100);
        client.send("02"); // CLOSE: motors off, the robot brakes to a stand
        client.connect();
        client.sip(s -> s.leftVel() == 0, 100); // motors disabled on a new connection
        client.send(4, 1); // ENABLE 1: the old set-point drives again
        client.sip(s -> s.leftVel() == 300, 100);
        client.send("1D");
        client.sip(s -> s.leftVel() == 0, 100);
        client.send("02");
        client.connect();
        client.send("1D"); // STOP before ENABLE: nothing left to resume
        client.send(4, 1);
        for (int i = 0; i < 10; i++) {
            assertThat(client.sip(s -> true, 5).leftVel()).isZero();
        }
    }

    @Test
    void sonarZeroTurnsTheRingOffAndOneBackOn() throws IOException {
        client.connect();
        client.sip(s -> !s.sonar().isEmpty(), 5);
        client.send(28, 0);
        StandardSip off = client.sip(s -> (s.flags() & 0x1E) == 0, 100);
        assertThat(client.sip(s -> true, 3).sonar()).isEmpty();
        assertThat(off.flags() & 0x1E).isZero();
        client.send(28, 1);
        StandardSip on = client.sip(s -> !s.sonar().isEmpty(), 100);
        assertThat(on.sonar()).allSatisfy(r -> assertThat(r.index()).isBetween(0, 15));
        assertThat(on.sonar().size()).as("readings fired since the last SIP: %s", on.sonar()).isBetween(1, 6);
    }
}
