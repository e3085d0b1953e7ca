package org.habla.sim.pioneer;

import java.io.ByteArrayOutputStream;
import java.util.List;

/**
 * Writes a standard SIP (type 0x32 stopped, 0x33 moving) the way a Pioneer 2 DX running ARCOS does: the classic
 * P2OS fields, then BATTERYX10, CHARGESTATE, ROTVEL, FAULTFLAGS, LATVEL, TEMPERATURE and state of charge.
 * Integers are little-endian; positions keep 15 bits and roll over.
 */
final class SipEncoder {

    static final int TYPE_STOPPED = 0x32;
    static final int TYPE_MOVING = 0x33;

    /** One sonar reading in the SIP: transducer index and range in sonar units. */
    record Reading(int index, int rangeUnits) {
    }

    /** What one SIP reports, already in the robot's units. */
    record Fields(boolean moving, int xPos, int yPos, int thPos, int leftVel, int rightVel, int batteryDv,
                  int stallAndBumpers, int flags, List<Reading> sonar, int rotVelDdegps) {
    }

    private SipEncoder() {
    }

    /** The SIP's data bytes (type first), ready for {@link ArcosFrames#frame}. */
    static byte[] encode(Fields f) {
        ByteArrayOutputStream b = new ByteArrayOutputStream(96);
        b.write(f.moving() ? TYPE_MOVING : TYPE_STOPPED);
        u16(b, f.xPos() & 0x7FFF);
        u16(b, f.yPos() & 0x7FFF);
        u16(b, f.thPos());
        u16(b, f.leftVel());
        u16(b, f.rightVel());
        b.write(f.batteryDv());
        u16(b, f.stallAndBumpers());
        u16(b, 0); // CONTROL: heading set-point, unused
        u16(b, f.flags());
        b.write(0); // COMPASS: none
        b.write(f.sonar().size());
        for (Reading r : f.sonar()) {
            b.write(r.index());
            u16(b, r.rangeUnits());
        }
        b.write(0); // GRIP_STATE
        b.write(0); // ANPORT
        b.write(0); // ANALOG
        b.write(0xFF); // DIGIN
        b.write(0xFF); // DIGOUT
        u16(b, f.batteryDv()); // BATTERYX10
        b.write(0); // CHARGESTATE: not charging
        u16(b, f.rotVelDdegps());
        u16(b, 0); // FAULTFLAGS
        u16(b, 0); // LATVEL
        b.write(-127 & 0xFF); // TEMPERATURE: no sensor
        b.write(100); // state of charge, %
        return b.toByteArray();
    }

    private static void u16(ByteArrayOutputStream b, int v) {
        b.write(v & 0xFF);
        b.write((v >>> 8) & 0xFF);
    }
}
