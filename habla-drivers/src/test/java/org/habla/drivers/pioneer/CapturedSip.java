package org.habla.drivers.pioneer;

/** The SIP the reference captured from AMRISim (model p2dx, at rest, empty map), 89 bytes on the wire. */
final class CapturedSip {

    static final String WIRE = "FA FB 56 32"
            + " 00 00 00 00 00 00 00 00 00 00 82 00 00 00 00 1F 00 00 10"
            + " 00 E1 48 01 E1 48 02 E1 48 03 E1 48 04 E1 48 05 E1 48 06 E1 48 07 E1 48"
            + " 08 E1 48 09 E1 48 0A E1 48 0B E1 48 0C E1 48 0D E1 48 0E E1 48 0F E1 48"
            + " 00 00 00 FF FF 82 00 00 00 00 00 00 00 00 81 00"
            + " 5C 9B";

    private CapturedSip() {
    }

    static byte[] wire() {
        return Hex.bytes(WIRE);
    }
}
