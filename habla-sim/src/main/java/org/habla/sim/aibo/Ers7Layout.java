package org.habla.sim.aibo;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * The ERS-7's tables as Tekkotsu 4.0 numbers them ({@code ERS7Info}) and the World State Serializer's
 * packet built from them (port 10031):
 * <pre>
 * "ERS-7\0"                         model name, NUL-terminated
 * timestamp      u32                ms since boot
 * frame          u32                sensor frame number, +4 per 32 ms update
 * 47  u32, then 47 × f32           outputs: 18 PID joints (rad), 27 LEDs, 2 ears
 * 11  u32, then 11 × f32           sensors: near, far, chest IR (mm), 3 accelerations, 5 power values
 * 10  u32, then 10 × f32           buttons: 4 paws, chin, head, back front/middle/rear, wireless switch
 * 18  u32, then 18 × f32           PID duty cycles (-1..1)
 * </pre>
 * All little-endian: 374 bytes.
 */
final class Ers7Layout {

    static final String MODEL = "ERS-7";
    static final int NUM_OUTPUTS = 47;
    static final int NUM_SENSORS = 11;
    static final int NUM_BUTTONS = 10;
    static final int NUM_PID_JOINTS = 18;
    static final int PACKET_BYTES = MODEL.length() + 1 + 6 * 4
            + (NUM_OUTPUTS + NUM_SENSORS + NUM_BUTTONS + NUM_PID_JOINTS) * 4;

    static final int HEAD_TILT = 12;
    static final int HEAD_PAN = 13;
    static final int HEAD_NOD = 14;
    static final int TAIL_TILT = 15;
    static final int MOUTH = 17;

    static final int HEAD_BUTTON = 5;
    static final int BACK_FRONT_BUTTON = 6;
    static final int BACK_MIDDLE_BUTTON = 7;
    static final int BACK_REAR_BUTTON = 8;

    /** Standing leg angles (rad), per leg rotator, elevator, knee: front legs, then back legs. */
    private static final double[] FRONT_LEG = {0.10, 0.15, 0.95};
    private static final double[] BACK_LEG = {-0.35, 0.15, 1.20};
    private static final double GAIT_SWING_RAD = 0.25;

    /** One packet's tables. */
    record Snapshot(float[] outputs, float[] sensors, float[] buttons, float[] duties) {
    }

    private Ers7Layout() {
    }

    /**
     * The tables of a standing or walking ERS-7.
     *
     * @param head      tilt, pan, nod in radians
     * @param gaitPhase the walk cycle's phase in radians, or NaN when standing still
     * @param irMm      near, far, chest IR distances in millimetres
     * @param buttons   the 10 button values
     * @param upS       seconds since boot (the battery drains slowly)
     */
    static Snapshot snapshot(double[] head, double gaitPhase, float[] irMm, float[] buttons, double upS) {
        float[] outputs = new float[NUM_OUTPUTS];
        boolean walking = !Double.isNaN(gaitPhase);
        for (int leg = 0; leg < 4; leg++) {
            double[] stand = leg < 2 ? FRONT_LEG : BACK_LEG;
            // diagonal pairs (LFr+RBk, RFr+LBk) swing together in a trot
            double swing = walking ? GAIT_SWING_RAD * Math.sin(gaitPhase + (leg == 0 || leg == 3 ? 0 : Math.PI)) : 0;
            outputs[leg * 3] = (float) (stand[0] + swing);
            outputs[leg * 3 + 1] = (float) stand[1];
            outputs[leg * 3 + 2] = (float) (stand[2] + (walking ? 0.5 * Math.max(0, swing) : 0));
        }
        outputs[HEAD_TILT] = (float) head[0];
        outputs[HEAD_PAN] = (float) head[1];
        outputs[HEAD_NOD] = (float) head[2];
        outputs[TAIL_TILT] = (float) Math.toRadians(30);
        outputs[MOUTH] = (float) Math.toRadians(-3);
        float[] sensors = new float[NUM_SENSORS];
        sensors[0] = irMm[0];
        sensors[1] = irMm[1];
        sensors[2] = irMm[2];
        sensors[3] = 0f;
        sensors[4] = 0f;
        sensors[5] = -9.81f;
        sensors[6] = (float) Math.max(0.05, 0.95 - upS / 36_000.0);
        sensors[7] = 30f;
        sensors[8] = 2_000f;
        sensors[9] = (float) (7.6 + sensors[6] * 0.8);
        sensors[10] = walking ? -1_200f : -600f;
        float[] duties = new float[NUM_PID_JOINTS];
        if (walking) {
            for (int j = 0; j < 12; j++) {
                duties[j] = (float) (0.08 * Math.cos(gaitPhase + j));
            }
        }
        return new Snapshot(outputs, sensors, buttons.clone(), duties);
    }

    /** The 374-byte World State packet. */
    static byte[] encode(Snapshot s, long timestampMs, long frame) {
        ByteBuffer b = ByteBuffer.allocate(PACKET_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        b.put(MODEL.getBytes(StandardCharsets.US_ASCII)).put((byte) 0);
        b.putInt((int) timestampMs).putInt((int) frame);
        for (float[] table : new float[][] {s.outputs(), s.sensors(), s.buttons(), s.duties()}) {
            b.putInt(table.length);
            for (float v : table) {
                b.putFloat(v);
            }
        }
        return b.array();
    }
}
