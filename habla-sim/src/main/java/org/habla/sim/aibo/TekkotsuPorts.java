package org.habla.sim.aibo;

/**
 * The ports of the simulated Aibo's Tekkotsu servers. {@link #withBase} shifts Tekkotsu's defaults
 * (10000 + n) all together, so several simulated Aibos can run on one machine; port 0 takes any free port
 * (tests).
 */
public record TekkotsuPorts(int controller, int eStop, int worldState, int walk, int head, int microphone,
        int speaker, int rawCam) {

    /** The port base of Tekkotsu's defaults. */
    public static final int DEFAULT_BASE = 10_000;

    /** Every server on a free port. */
    public static final TekkotsuPorts ANY_FREE = new TekkotsuPorts(0, 0, 0, 0, 0, 0, 0, 0);

    public TekkotsuPorts {
        for (int p : new int[] {controller, eStop, worldState, walk, head, microphone, speaker, rawCam}) {
            if (p < 0 || p > 65_535) {
                throw new IllegalArgumentException("a port must be in 0..65535, was " + p);
            }
        }
    }

    /** Tekkotsu's default ports moved by {@code base - 10000}: base 20000 puts the walk server on 20050. */
    public static TekkotsuPorts withBase(int base) {
        int d = base - DEFAULT_BASE;
        if (base < 1_024 || 10_071 + d > 65_535) {
            throw new IllegalArgumentException("port base must be in 1024.." + (65_535 - 71) + ", was " + base);
        }
        return new TekkotsuPorts(10_020 + d, 10_053 + d, 10_031 + d, 10_050 + d, 10_052 + d, 10_070 + d, 10_071 + d,
                10_011 + d);
    }
}
