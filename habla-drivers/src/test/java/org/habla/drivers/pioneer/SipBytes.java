package org.habla.drivers.pioneer;

import java.io.ByteArrayOutputStream;
import java.util.LinkedHashMap;
import java.util.Map;

/** Builds SIP packets field by field in the robot's units, as a robot would send them; for tests. */
final class SipBytes {

    int type = StandardSip.TYPE_STOPPED;
    int xPos;
    int yPos;
    int thPos;
    int leftVel;
    int rightVel;
    int battery = 130;
    int stallAndBumpers;
    int flags = 0x1F;
    final Map<Integer, Integer> sonar = new LinkedHashMap<>();
    /** Whether to append the newer firmware's tail (BATTERYX10 .. SoC). */
    boolean tail;
    int batteryX10 = 130;
    int rotVel;
    /** The controller's temperature in the tail, °C; -127 (0x81) says it has none. */
    int temperature = -127;

    SipBytes sonar(int index, int range) {
        sonar.put(index, range);
        return this;
    }

    ArcosPacket packet() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        b.write(type);
        u16(b, xPos);
        u16(b, yPos);
        u16(b, thPos);
        u16(b, leftVel);
        u16(b, rightVel);
        b.write(battery);
        u16(b, stallAndBumpers);
        u16(b, 0);
        u16(b, flags);
        b.write(0);
        b.write(sonar.size());
        sonar.forEach((i, r) -> {
            b.write(i);
            u16(b, r);
        });
        b.writeBytes(new byte[] {0, 0, 0, (byte) 0xFF, (byte) 0xFF});
        if (tail) {
            u16(b, batteryX10);
            b.write(0);
            u16(b, rotVel);
            u16(b, 0);
            u16(b, 0);
            b.write(temperature & 0xFF);
            b.write(77);
        }
        return ArcosPacket.of(b.toByteArray());
    }

    byte[] wire() {
        return packet().toWire();
    }

    private static void u16(ByteArrayOutputStream b, int v) {
        b.write(v & 0xFF);
        b.write((v >>> 8) & 0xFF);
    }
}
