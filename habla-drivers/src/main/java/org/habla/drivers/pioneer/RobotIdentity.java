package org.habla.drivers.pioneer;

import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * What the robot says it is in its SYNC2 reply: its name (user-set on a real robot, {@code AMRISim} or
 * {@code MobileSim} in a simulator), its class ({@code Pioneer}) and its subclass ({@code p2dx}).
 */
record RobotIdentity(String name, String robotClass, String subclass) {

    static final RobotIdentity UNKNOWN = new RobotIdentity("", "", "");

    RobotIdentity {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(robotClass, "robotClass");
        Objects.requireNonNull(subclass, "subclass");
    }

    /**
     * Reads the three NUL-terminated strings of a SYNC2 reply. A reply cut short yields empty strings for
     * what is missing: the identity is for people, and the session works without it.
     */
    static RobotIdentity fromSync2(ArcosPacket reply) {
        byte[] p = reply.payload();
        String[] parts = {"", "", ""};
        int from = 0;
        for (int i = 0; i < parts.length && from < p.length; i++) {
            int nul = from;
            while (nul < p.length && p[nul] != 0) {
                nul++;
            }
            parts[i] = new String(p, from, nul - from, StandardCharsets.ISO_8859_1);
            from = nul + 1;
        }
        return new RobotIdentity(parts[0], parts[1], parts[2]);
    }
}
