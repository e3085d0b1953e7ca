package org.habla.drivers.pioneer;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;

/**
 * One standard server information packet (SIP, type 0x32 or 0x33) in the robot's own units, field by
 * field as the robot sent it. Converting to SI units is {@link SipTranslator}'s job.
 *
 * <p>Fields up to {@code digOut} end a classic P2OS SIP and are always present; newer firmware appends
 * the optional fields, which are read only while bytes remain.
 *
 * @param moving          type 0x33 (moving) rather than 0x32 (stopped); simulators always send 0x32
 * @param xPos            x position, 15 significant bits, in position units (× DistConvFactor = mm)
 * @param yPos            y position, as {@code xPos}
 * @param thPos           heading in angle units (× AngleConvFactor = rad)
 * @param leftVel         left wheel velocity (× VelConvFactor = mm/s)
 * @param rightVel        right wheel velocity (× VelConvFactor = mm/s)
 * @param batteryDv       battery voltage, 0.1 V
 * @param stallAndBumpers bit 0 left stall, bits 1–7 rear bumpers, bit 8 right stall, bits 9–15 front bumpers
 * @param control         heading set-point (angle units)
 * @param flags           bit 0 motors enabled, bits 1–4 sonar arrays on, bit 5 stop button, bit 6 e-stall
 * @param compass         compass byte (2° units on robots that have one)
 * @param sonar           the sonar readings this SIP carries (only new ones on a real robot)
 * @param gripState       gripper state (P2OS: low byte of TIMER)
 * @param anPort          selected analog port (P2OS: high byte of TIMER)
 * @param analog          analog reading, 0–255 = 0–5 V
 * @param digIn           user digital inputs
 * @param digOut          user digital outputs
 * @param batteryX10      battery voltage, 0.1 V, two bytes (newer firmware)
 * @param chargeState     -1 unknown, 0 not charging, 1 bulk, 2 overcharge, 3 float, 4 balance
 * @param rotVelDdegps    actual rotational velocity, 0.1 deg/s
 * @param faultFlags      fault bits
 * @param latVel          lateral velocity, mm/s (Seekur)
 * @param temperatureC    controller temperature, °C (-127 = none)
 * @param stateOfCharge   battery state of charge, %
 */
public record StandardSip(boolean moving, int xPos, int yPos, int thPos, int leftVel, int rightVel, int batteryDv,
        int stallAndBumpers, int control, int flags, int compass, List<SonarReading> sonar, int gripState,
        int anPort, int analog, int digIn, int digOut, OptionalInt batteryX10, OptionalInt chargeState,
        OptionalInt rotVelDdegps, OptionalInt faultFlags, OptionalInt latVel, OptionalInt temperatureC,
        OptionalInt stateOfCharge) {

    /** The packet type of a SIP while the motors are stopped. */
    public static final int TYPE_STOPPED = 0x32;
    /** The packet type of a SIP while the robot moves. */
    public static final int TYPE_MOVING = 0x33;

    /** One sonar reading: the transducer's index (0–31) and its range in sonar units (× RangeConvFactor = mm). */
    public record SonarReading(int index, int range) {
    }

    public StandardSip {
        sonar = List.copyOf(sonar);
    }

    /** Whether a packet of this type is a standard SIP. */
    public static boolean isSip(int type) {
        return type == TYPE_STOPPED || type == TYPE_MOVING;
    }

    /**
     * Decodes a SIP.
     *
     * @throws IllegalArgumentException if the packet is not a SIP or ends before the classic fields do
     */
    public static StandardSip parse(ArcosPacket packet) {
        if (!isSip(packet.type())) {
            throw new IllegalArgumentException(String.format("packet type 0x%02X is not a SIP", packet.type()));
        }
        PacketCursor c = new PacketCursor(packet.payload());
        int xPos = c.u16("XPOS") & 0x7FFF;
        int yPos = c.u16("YPOS") & 0x7FFF;
        int thPos = c.s16("THPOS");
        int leftVel = c.s16("L VEL");
        int rightVel = c.s16("R VEL");
        int battery = c.u8("BATTERY");
        int stallAndBumpers = c.u16("STALL AND BUMPERS");
        int control = c.s16("CONTROL");
        int flags = c.u16("FLAGS");
        int compass = c.u8("COMPASS");
        int count = c.u8("SONAR COUNT");
        List<SonarReading> sonar = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            sonar.add(new SonarReading(c.u8("sonar NUMBER " + i), c.u16("sonar RANGE " + i)));
        }
        int gripState = c.u8("GRIP_STATE");
        int anPort = c.u8("ANPORT");
        int analog = c.u8("ANALOG");
        int digIn = c.u8("DIGIN");
        int digOut = c.u8("DIGOUT");
        OptionalInt batteryX10 = c.remaining() >= 2 ? OptionalInt.of(c.u16("BATTERYX10")) : OptionalInt.empty();
        OptionalInt chargeState = c.remaining() >= 1 ? OptionalInt.of(c.s8("CHARGESTATE")) : OptionalInt.empty();
        OptionalInt rotVel = c.remaining() >= 2 ? OptionalInt.of(c.s16("ROTVEL")) : OptionalInt.empty();
        OptionalInt faultFlags = c.remaining() >= 2 ? OptionalInt.of(c.u16("FAULTFLAGS")) : OptionalInt.empty();
        OptionalInt latVel = c.remaining() >= 2 ? OptionalInt.of(c.s16("LATVEL")) : OptionalInt.empty();
        OptionalInt temperature = c.remaining() >= 1 ? OptionalInt.of(c.s8("TEMPERATURE")) : OptionalInt.empty();
        OptionalInt soc = c.remaining() >= 1 ? OptionalInt.of(c.u8("SoC")) : OptionalInt.empty();
        return new StandardSip(packet.type() == TYPE_MOVING, xPos, yPos, thPos, leftVel, rightVel, battery,
                stallAndBumpers, control, flags, compass, sonar, gripState, anPort, analog, digIn, digOut, batteryX10,
                chargeState, rotVel, faultFlags, latVel, temperature, soc);
    }

    /** Bit 0 of the low byte. */
    public boolean leftStalled() {
        return (stallAndBumpers & 0x0001) != 0;
    }

    /** Bit 0 of the high byte. */
    public boolean rightStalled() {
        return (stallAndBumpers & 0x0100) != 0;
    }

    /** Front bumper {@code i} (0 first), bit 9 + i. */
    public boolean frontBumper(int i) {
        return (stallAndBumpers & (1 << (9 + i))) != 0;
    }

    /** Rear bumper {@code i} (0 first), bit 1 + i. */
    public boolean rearBumper(int i) {
        return (stallAndBumpers & (1 << (1 + i))) != 0;
    }

    public boolean motorsEnabled() {
        return (flags & 0x0001) != 0;
    }
}
