package org.habla.sim.pioneer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.habla.drivers.pioneer.ArcosPacket;
import org.habla.drivers.pioneer.StandardSip;
import org.junit.jupiter.api.Test;

/** The simulator's SIPs decoded by the driver's own SIP parser, field by field. */
class SipEncoderTest {

    @Test
    void everyFieldReadsBackThroughTheDriversParser() {
        SipEncoder.Fields f = new SipEncoder.Fields(true, -5, 32_000, -1024, -93, 93, 130, 0x0101 | (1 << 11), 0x1F,
                List.of(new SipEncoder.Reading(3, 18_657), new SipEncoder.Reading(11, 400)), 300);
        StandardSip sip = StandardSip.parse(ArcosPacket.of(SipEncoder.encode(f)));
        assertThat(sip.moving()).isTrue();
        assertThat(sip.xPos()).isEqualTo(0x7FFF - 4); // -5 rolls over within 15 bits
        assertThat(sip.yPos()).isEqualTo(32_000);
        assertThat(sip.thPos()).isEqualTo(-1024);
        assertThat(sip.leftVel()).isEqualTo(-93);
        assertThat(sip.rightVel()).isEqualTo(93);
        assertThat(sip.batteryDv()).isEqualTo(130);
        assertThat(sip.leftStalled()).isTrue();
        assertThat(sip.rightStalled()).isTrue();
        assertThat(sip.frontBumper(2)).isTrue();
        assertThat(sip.frontBumper(1)).isFalse();
        assertThat(sip.motorsEnabled()).isTrue();
        assertThat(sip.sonar()).containsExactly(new StandardSip.SonarReading(3, 18_657),
                new StandardSip.SonarReading(11, 400));
        assertThat(sip.digIn()).isEqualTo(0xFF);
        assertThat(sip.batteryX10()).hasValue(130);
        assertThat(sip.rotVelDdegps()).hasValue(300);
        assertThat(sip.temperatureC()).hasValue(-127);
        assertThat(sip.stateOfCharge()).hasValue(100);
    }

    @Test
    void aSipWithAFullSonarRingStaysWithinTheSendLimit() {
        List<SipEncoder.Reading> ring = new java.util.ArrayList<>();
        for (int i = 0; i < 16; i++) {
            ring.add(new SipEncoder.Reading(i, 1000 + i));
        }
        byte[] data = SipEncoder.encode(new SipEncoder.Fields(false, 0, 0, 0, 0, 0, 130, 0, 0x1E, ring, 0));
        assertThat(ArcosFrames.frame(data).length - 3).isLessThanOrEqualTo(ArcosFrames.MAX_SEND_COUNT);
        assertThat(StandardSip.parse(ArcosPacket.of(data)).sonar()).hasSize(16);
    }
}
