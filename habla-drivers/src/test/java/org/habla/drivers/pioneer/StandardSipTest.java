package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class StandardSipTest {

    private static ArcosPacket decodeOne(byte[] wire) {
        List<ArcosPacket> out = new ArrayList<>();
        new ArcosPacketDecoder().push(wire, new ArcosPacketDecoder.Listener() {
            @Override
            public void packet(ArcosPacket packet) {
                out.add(packet);
            }

            @Override
            public void malformed(String what) {
                throw new AssertionError(what);
            }
        });
        assertThat(out).hasSize(1);
        return out.get(0);
    }

    @Test
    void theCapturedSipDecodesFieldByFieldAsTheReferenceReadsIt() {
        StandardSip sip = StandardSip.parse(decodeOne(CapturedSip.wire()));
        assertThat(sip.moving()).isFalse();
        assertThat(sip.xPos()).isZero();
        assertThat(sip.yPos()).isZero();
        assertThat(sip.thPos()).isZero();
        assertThat(sip.leftVel()).isZero();
        assertThat(sip.rightVel()).isZero();
        assertThat(sip.batteryDv()).isEqualTo(130);
        assertThat(sip.stallAndBumpers()).isZero();
        assertThat(sip.control()).isZero();
        assertThat(sip.flags()).isEqualTo(0x1F);
        assertThat(sip.motorsEnabled()).isTrue();
        assertThat(sip.compass()).isZero();
        assertThat(sip.sonar()).hasSize(16);
        for (int i = 0; i < 16; i++) {
            assertThat(sip.sonar().get(i)).isEqualTo(new StandardSip.SonarReading(i, 18657));
        }
        assertThat(sip.gripState()).isZero();
        assertThat(sip.anPort()).isZero();
        assertThat(sip.analog()).isZero();
        assertThat(sip.digIn()).isEqualTo(0xFF);
        assertThat(sip.digOut()).isEqualTo(0xFF);
        assertThat(sip.batteryX10()).hasValue(130);
        assertThat(sip.chargeState()).hasValue(0);
        assertThat(sip.rotVelDdegps()).hasValue(0);
        assertThat(sip.faultFlags()).hasValue(0);
        assertThat(sip.latVel()).hasValue(0);
        assertThat(sip.temperatureC()).hasValue(-127);
        assertThat(sip.stateOfCharge()).hasValue(0);
    }

    @Test
    void aClassicP2osSipWithoutTheTailHasNoOptionalFields() {
        SipBytes b = new SipBytes();
        b.xPos = 1234;
        b.yPos = 0x7FFF;
        b.thPos = -1024;
        b.leftVel = -93;
        b.rightVel = 93;
        b.sonar(3, 500);
        StandardSip sip = StandardSip.parse(b.packet());
        assertThat(sip.xPos()).isEqualTo(1234);
        assertThat(sip.yPos()).isEqualTo(0x7FFF);
        assertThat(sip.thPos()).isEqualTo(-1024);
        assertThat(sip.leftVel()).isEqualTo(-93);
        assertThat(sip.rightVel()).isEqualTo(93);
        assertThat(sip.sonar()).containsExactly(new StandardSip.SonarReading(3, 500));
        assertThat(sip.batteryX10()).isEmpty();
        assertThat(sip.rotVelDdegps()).isEmpty();
        assertThat(sip.stateOfCharge()).isEmpty();
    }

    @Test
    void thePositionKeepsOnlyFifteenBits() {
        SipBytes b = new SipBytes();
        b.xPos = 0x8005;
        assertThat(StandardSip.parse(b.packet()).xPos()).isEqualTo(5);
    }

    @Test
    void stallAndBumperBitsAreReadFromTheirBytes() {
        SipBytes b = new SipBytes();
        b.stallAndBumpers = 0x0101 | (1 << 9) | (1 << 13) | (1 << 2);
        StandardSip sip = StandardSip.parse(b.packet());
        assertThat(sip.leftStalled()).isTrue();
        assertThat(sip.rightStalled()).isTrue();
        assertThat(sip.frontBumper(0)).isTrue();
        assertThat(sip.frontBumper(1)).isFalse();
        assertThat(sip.frontBumper(4)).isTrue();
        assertThat(sip.rearBumper(0)).isFalse();
        assertThat(sip.rearBumper(1)).isTrue();
    }

    @Test
    void typeThirtyThreeMeansMoving() {
        SipBytes b = new SipBytes();
        b.type = StandardSip.TYPE_MOVING;
        assertThat(StandardSip.parse(b.packet()).moving()).isTrue();
    }

    @Test
    void aSipThatEndsInsideItsSonarReadingsIsRefusedNamingTheField() {
        byte[] data = new SipBytes().sonar(0, 1).sonar(1, 2).packet().data();
        data[19] = 5;
        ArcosPacket cut = ArcosPacket.of(java.util.Arrays.copyOf(data, 27));
        assertThatThrownBy(() -> StandardSip.parse(cut)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("sonar");
    }

    @Test
    void aPacketOfAnotherTypeIsNotASip() {
        assertThatThrownBy(() -> StandardSip.parse(ArcosPacket.of((byte) 0x20, (byte) 0)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("0x20");
    }
}
