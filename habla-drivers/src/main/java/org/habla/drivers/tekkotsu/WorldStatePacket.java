package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.util.Optional;

/**
 * One packet of Tekkotsu's World State Serializer (port 10031), layout of Tekkotsu 4.0 and later.
 * <pre>
 * model name  ASCII, NUL-terminated ("ERS-7")
 * timestamp   u32  ms since boot
 * frame       u32  sensor frame number
 * NumOutputs  u32, then NumOutputs  × f32   joint positions (rad), LED values
 * NumSensors  u32, then NumSensors  × f32   IR (mm), accelerations (m/s²), power
 * NumButtons  u32, then NumButtons  × f32   paws, chin, head and back touch
 * NumPIDJoints u32, then NumPIDJoints × f32 motor duty cycles
 * </pre>
 * All little-endian; 374 bytes for an ERS-7. There is no length prefix: the counts frame the packet.
 */
record WorldStatePacket(String model, long timestampMs, long frame, float[] outputs, float[] sensors, float[] buttons,
        float[] duties) {

    /** The 4 bytes every packet of the 4.0+ layout starts with. */
    static final byte[] MAGIC = {'E', 'R', 'S', '-'};

    /** No Tekkotsu model has more entries in any table; a larger count means the stream is out of step. */
    static final int MAX_COUNT = 128;

    private static final int MAX_MODEL_CHARS = 16;

    /** Reads the rest of a packet whose first 4 bytes, {@link #MAGIC}, have been read already. */
    static WorldStatePacket readAfterMagic(WireInput in) throws IOException {
        String model = "ERS-" + in.cString(MAX_MODEL_CHARS, "model name");
        long timestamp = in.u32("timestamp");
        long frame = in.u32("frame number");
        float[] outputs = floats(in, "outputs");
        float[] sensors = floats(in, "sensors");
        float[] buttons = floats(in, "buttons");
        float[] duties = floats(in, "PID duties");
        return new WorldStatePacket(model, timestamp, frame, outputs, sensors, buttons, duties);
    }

    private static float[] floats(WireInput in, String table) throws IOException {
        long count = in.u32("number of " + table);
        if (count > MAX_COUNT) {
            throw new WireInput.MalformedFieldException("number of " + table + " is " + count
                    + ", more than any Tekkotsu robot has (" + MAX_COUNT + ")");
        }
        float[] values = new float[(int) count];
        for (int i = 0; i < values.length; i++) {
            values[i] = in.f32(table + "[" + i + "]");
        }
        return values;
    }

    /** Why this packet is not an ERS-7 packet this driver can decode, or empty if it is one. */
    Optional<String> ers7Mismatch() {
        if (!model.equals(Ers7.MODEL)) {
            return Optional.of("World State packet is from a " + model + ", not an " + Ers7.MODEL
                    + " (the tekkotsu driver decodes the ERS-7 layout only)");
        }
        String counts = count("outputs", outputs.length, Ers7.NUM_OUTPUTS) + count("sensors", sensors.length,
                Ers7.NUM_SENSORS) + count("buttons", buttons.length, Ers7.NUM_BUTTONS)
                + count("PID joints", duties.length, Ers7.NUM_PID_JOINTS);
        if (!counts.isEmpty()) {
            return Optional.of("World State packet says " + Ers7.MODEL + " but its counts do not match the "
                    + Ers7.MODEL + " tables:" + counts + " (a different Tekkotsu version or robot model?)");
        }
        return Optional.empty();
    }

    private static String count(String table, int actual, int expected) {
        return actual == expected ? "" : " " + actual + " " + table + " (expected " + expected + ")";
    }
}
