package org.habla.drivers.pioneer;

import java.util.Objects;
import java.util.OptionalInt;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code status} reading of a Pioneer, from one SIP: its FLAGS word and what it says, whether it moves, who it
 * said it is in the handshake, the packets the session ignored, and what newer firmware adds to a SIP.
 *
 * @param flags            the SIP's FLAGS word
 * @param moving           whether the SIP says the robot is moving
 * @param robot            who the robot said it is
 * @param ignoredPackets   the packets other than SIPs the session has ignored
 * @param chargeState      the charger's state; null when the firmware does not send it
 * @param faultFlags       the fault bits; null when the firmware does not send them
 * @param temperatureC     the controller's temperature; null when the firmware does not send it or has none
 * @param stateOfChargePct the battery's state of charge; null when the firmware does not send it
 */
record StatusReading(int flags, boolean moving, RobotIdentity robot, long ignoredPackets, Integer chargeState,
        Integer faultFlags, Integer temperatureC, Integer stateOfChargePct) implements RecordForm {

    /** What a SIP's TEMPERATURE says when the controller has no reading. */
    private static final int NO_TEMPERATURE = -127;

    static final RecordLayout<StatusReading> LAYOUT = RecordLayout.of(StatusReading.class)
            .flag("motorsEnabled", s -> (s.flags & 0x01) != 0).doc("the motors are enabled (FLAGS bit 0)")
            .flag("sonarOn", s -> (s.flags & 0x1E) != 0).doc("some sonar array is on (FLAGS bits 1-4)")
            .flag("stopButton", s -> (s.flags & 0x20) != 0).doc("the stop button is pressed (FLAGS bit 5)")
            .flag("eStall", s -> (s.flags & 0x40) != 0).doc("the e-stop stalls the motors (FLAGS bit 6)")
            .flag("moving", StatusReading::moving).doc("the SIP says the robot is moving")
            .longInteger("flags", StatusReading::flags).doc("the SIP's FLAGS word")
            .text("robotName", s -> s.robot.name()).doc("the robot's name, from the handshake; empty when not said")
            .text("robotClass", s -> s.robot.robotClass()).doc("the robot's class, from the handshake")
            .text("robotSubclass", s -> s.robot.subclass()).doc("the robot's subclass, from the handshake")
            .longInteger("ignoredPackets", StatusReading::ignoredPackets)
            .doc("the packets other than SIPs the session has ignored")
            .optionalLongInteger("chargeState", s -> wide(s.chargeState))
            .doc("the charger: -1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float, 4 balance; newer firmware")
            .optionalLongInteger("faultFlags", s -> wide(s.faultFlags)).doc("the fault bits; newer firmware")
            .optionalLongInteger("temperatureC", s -> wide(s.temperatureC)).unit("°C")
            .doc("the controller's temperature; newer firmware, when it has a reading")
            .optionalLongInteger("stateOfChargePct", s -> wide(s.stateOfChargePct)).unit("%")
            .doc("the battery's state of charge; newer firmware")
            .build();

    StatusReading {
        Objects.requireNonNull(robot, "robot");
    }

    static StatusReading of(StandardSip sip, RobotIdentity robot, long ignoredPackets) {
        OptionalInt t = sip.temperatureC();
        return new StatusReading(sip.flags(), sip.moving(), robot, ignoredPackets, orNull(sip.chargeState()),
                orNull(sip.faultFlags()), t.isPresent() && t.getAsInt() != NO_TEMPERATURE ? t.getAsInt() : null,
                orNull(sip.stateOfCharge()));
    }

    @Override
    public RecordLayout<StatusReading> layout() {
        return LAYOUT;
    }

    private static Integer orNull(OptionalInt v) {
        return v.isPresent() ? v.getAsInt() : null;
    }

    private static Long wide(Integer v) {
        return v == null ? null : v.longValue();
    }
}
