package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;
import org.habla.config.ParamsJson;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class ArcosSessionTest {

    private final RecordingSink sink = new RecordingSink();
    private TinyArcosRobot robot;
    private Socket socket;

    @AfterEach
    void closeEverything() throws IOException {
        if (socket != null) {
            socket.close();
        }
        if (robot != null) {
            robot.close();
        }
    }

    private InputStream in;
    private OutputStream out;

    private void connect(TinyArcosRobot r) throws IOException {
        robot = r;
        socket = new Socket(InetAddress.getLoopbackAddress(), r.port());
        socket.setSoTimeout(15_000);
        in = new BufferedInputStream(socket.getInputStream());
        out = new BufferedOutputStream(socket.getOutputStream());
    }

    private static ArcosSession session(String paramsJson) throws IOException {
        return new ArcosSession(ParamsJson.of(PioneerParams.class, paramsJson));
    }

    @Test
    void theHandshakeSyncsThenOpensStopsPulsesEnablesTheMotorsAndTurnsSonarOn() throws Exception {
        connect(new TinyArcosRobot());
        new ArcosSession(PioneerParams.defaults()).handshake(in, out, sink);
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC0.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC1.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC2.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.OPEN.packet());
        assertThat(robot.nextReceived()).as("set-points from an earlier session are cleared before anything else")
                .isEqualTo(ArcosCommand.STOP.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.PULSE.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.ENABLE.packet(1));
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SONAR.packet(1));
        assertThat(sink.robotInfo()).singleElement().satisfies(info -> {
            assertThat(info.path("name").asText()).isEqualTo("Tiny");
            assertThat(info.path("class").asText()).isEqualTo("Pioneer");
            assertThat(info.path("subclass").asText()).isEqualTo("p2dx");
            assertThat(info.path("protocol").asText()).isEqualTo("ARCOS");
        });
    }

    @Test
    void withEnableMotorsOffTheHandshakeLeavesTheMotorsAlone() throws Exception {
        connect(new TinyArcosRobot());
        session("{\"enableMotors\": false}").handshake(in, out, sink);
        for (int i = 0; i < 6; i++) {
            robot.nextReceived();
        }
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SONAR.packet(1));
    }

    @Test
    void aRobotStillOpenFromAnEarlierClientIsClosedAndSyncedAgain() throws Exception {
        connect(new TinyArcosRobot().stillOpen());
        new ArcosSession(PioneerParams.defaults()).handshake(in, out, sink);
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC0.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.CLOSE.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC0.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC1.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.SYNC2.packet());
        assertThat(robot.nextReceived()).isEqualTo(ArcosCommand.OPEN.packet());
        assertThat(sink.robotInfo()).hasSize(1);
    }

    @Test
    void aRobotThatNeverAnswersFailsTheHandshakeWhenTheReadTimesOut() throws Exception {
        connect(new TinyArcosRobot().silent());
        socket.setSoTimeout(200);
        assertThatThrownBy(() -> new ArcosSession(PioneerParams.defaults()).handshake(in, out, sink))
                .isInstanceOf(SocketTimeoutException.class);
        assertThat(sink.robotInfo()).isEmpty();
    }

    @Test
    void sipsAfterTheHandshakeBecomeReadingsAndBadBytesAreCountedOnTheWay() throws Exception {
        connect(new TinyArcosRobot());
        ArcosSession session = new ArcosSession(PioneerParams.defaults());
        session.handshake(in, out, sink);
        byte[] corrupted = CapturedSip.wire();
        corrupted[30] ^= 0x55;
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        stream.writeBytes(corrupted);
        stream.writeBytes(Hex.bytes("01 02 03"));
        stream.writeBytes(ArcosPacket.of(Hex.bytes("20 50 00")).toWire());
        stream.writeBytes(CapturedSip.wire());
        robot.send(stream.toByteArray());
        while (sink.on("odometry").isEmpty()) {
            session.readNext(in, sink);
        }
        assertThat(sink.malformed()).hasSize(2);
        assertThat(sink.on("sonar")).hasSize(1);
        assertThat(((NumberValue) sink.last("battery")).value()).isEqualTo(13.0);
        RecordValue status = (RecordValue) sink.last("status");
        assertThat(status.text("robotName")).isEqualTo("Tiny");
        assertThat(status.get("ignoredPackets").asLong()).as("the CONFIGpac").isEqualTo(1);
    }

    @Test
    void aRobotHangingUpMidPacketEndsTheSessionWithoutAReadingFromTheFragment() throws Exception {
        connect(new TinyArcosRobot());
        ArcosSession session = new ArcosSession(PioneerParams.defaults());
        session.handshake(in, out, sink);
        byte[] sip = CapturedSip.wire();
        robot.send(java.util.Arrays.copyOf(sip, 50));
        robot.hangUp();
        assertThatThrownBy(() -> session.readNext(in, sink)).isInstanceOf(EOFException.class);
        assertThat(sink.readings()).isEmpty();
    }

    @Test
    void motionIsVelThenRvelInMillimetresAndDegrees() throws IOException {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        new ArcosSession(PioneerParams.defaults()).write("motion", VectorValue.of(0.3, -Math.toRadians(30)), wire);
        assertThat(Hex.text(wire.toByteArray())).isEqualTo("FA FB 06 0B 3B 2C 01 37 3C FA FB 06 15 1B 1E 00 33 1B");
    }

    @Test
    void motionBeyondTheRobotsLimitsIsClamped() throws IOException {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        session("{\"maxVelMps\": 0.5, \"maxRotVelRadps\": 1.0}").write("motion", VectorValue.of(-9.0, 40.0), wire);
        assertThat(Hex.text(wire.toByteArray())).isEqualTo(
                Hex.text(ArcosCommand.VEL.packet(-500).toWire()) + " " + Hex.text(ArcosCommand.RVEL.packet(57).toWire()));
    }

    @Test
    void aMotionCommandThatIsNotTwoFiniteNumbersStopsTheRobotInstead() throws IOException {
        ArcosSession session = new ArcosSession(PioneerParams.defaults());
        for (var bad : java.util.List.of(VectorValue.of(Double.NaN, 0), VectorValue.of(0.1), VectorValue.of(0.1, 0, 0),
                VectorValue.of(Double.POSITIVE_INFINITY, 0), new TextValue("forward"))) {
            ByteArrayOutputStream wire = new ByteArrayOutputStream();
            session.write("motion", bad, wire);
            assertThat(wire.toByteArray()).as(bad.toString()).isEqualTo(ArcosCommand.STOP.packet().toWire());
        }
    }

    @Test
    void sonarPowerTurnsTheSonarOnAndOff() throws IOException {
        ArcosSession session = new ArcosSession(PioneerParams.defaults());
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        session.write("sonar-power", new NumberValue(0), wire);
        session.write("sonar-power", new NumberValue(1), wire);
        session.write("sonar-power", new NumberValue(Double.NaN), wire);
        assertThat(Hex.text(wire.toByteArray())).isEqualTo("FA FB 06 1C 3B 00 00 1C 3B FA FB 06 1C 3B 01 00 1D 3B");
    }

    @Test
    void stopIsStopKeepAliveIsPulseAndGoodbyeIsClose() throws IOException {
        ArcosSession session = new ArcosSession(PioneerParams.defaults());
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        session.stopMotion(wire);
        session.keepAlive(wire);
        session.goodbye(wire);
        assertThat(Hex.text(wire.toByteArray())).isEqualTo("FA FB 03 1D 00 1D FA FB 03 00 00 00 FA FB 03 02 00 02");
        assertThat(session.keepAlivePeriod()).contains(Duration.ofMillis(500));
    }

    @Test
    void aCommandOnAChannelTheConnectionDoesNotCarryIsAnError() {
        assertThatThrownBy(() -> new ArcosSession(PioneerParams.defaults())
                .write("speaker", new NumberValue(1), new ByteArrayOutputStream()))
                .isInstanceOf(IOException.class).hasMessageContaining("speaker");
    }
}
