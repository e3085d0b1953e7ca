package org.habla.drivers.tekkotsu;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/** Builds Tekkotsu packets field by field, as the reference lays them out, for tests. */
final class TekkotsuPackets {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    static TekkotsuPackets start() {
        return new TekkotsuPackets();
    }

    TekkotsuPackets u8(int v) {
        out.write(v);
        return this;
    }

    TekkotsuPackets u16(int v) {
        out.write(v & 0xff);
        out.write(v >>> 8 & 0xff);
        return this;
    }

    TekkotsuPackets u32(long v) {
        ByteBuffer b = ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt((int) v);
        out.writeBytes(b.array());
        return this;
    }

    TekkotsuPackets f32(float v) {
        return u32(Float.floatToIntBits(v));
    }

    TekkotsuPackets floats(float... values) {
        u32(values.length);
        for (float v : values) {
            f32(v);
        }
        return this;
    }

    TekkotsuPackets ascii(String s) {
        out.writeBytes(s.getBytes(StandardCharsets.US_ASCII));
        return this;
    }

    TekkotsuPackets cString(String s) {
        return ascii(s).u8(0);
    }

    TekkotsuPackets loadSave(String s) {
        return u32(s.length()).ascii(s).u8(0);
    }

    TekkotsuPackets bytes(byte[] b) {
        out.writeBytes(b);
        return this;
    }

    byte[] build() {
        return out.toByteArray();
    }

    /** The floats 0, 1, 2, ... scaled by {@code step} and offset by {@code base}, so every field is distinct. */
    static float[] ramp(int n, float base, float step) {
        float[] f = new float[n];
        for (int i = 0; i < n; i++) {
            f[i] = base + i * step;
        }
        return f;
    }

    /** An ERS-7 World State packet with distinct values in every field. */
    static byte[] worldState(String model, float[] outputs, float[] sensors, float[] buttons, float[] duties) {
        return start().cString(model).u32(123_456).u32(4_000)
                .floats(outputs).floats(sensors).floats(buttons).floats(duties).build();
    }

    static float[] ers7Outputs() {
        return ramp(Ers7.NUM_OUTPUTS, -1.0f, 0.03f);
    }

    static float[] ers7Sensors() {
        // near 234 mm, far 876 mm, chest 432 mm, accel b/l/d, power remain/thermo/capacity/voltage/current
        return new float[] {234f, 876f, 432f, -0.5f, 1.25f, -9.75f, 0.8f, 31f, 2000f, 8.2f, -400f};
    }

    static float[] ers7Buttons() {
        // paws 0/1, chin, head touch 0.5, back front/middle/rear, then an out-of-range wireless value
        return new float[] {1f, 0f, 1f, 0f, 1f, 0.5f, 0.25f, 0.75f, 1.5f, 3f};
    }

    static byte[] ers7WorldState() {
        return worldState("ERS-7", ers7Outputs(), ers7Sensors(), ers7Buttons(),
                ramp(Ers7.NUM_PID_JOINTS, 0f, 0.01f));
    }

    /** A raw-camera packet header. */
    static TekkotsuPackets cameraHeader(int encoding, int compression, int width, int height, long frame) {
        return start().loadSave("TekkotsuImage").u32(encoding).u32(compression).u32(width).u32(height)
                .u32(98_765).u32(frame);
    }

    /** A channel section header, up to and including its format string. */
    TekkotsuPackets section(int width, int height, int layer, int channel, String format) {
        return loadSave("FbkImage").u32(width).u32(height).u32(layer).u32(channel).loadSave(format);
    }

    /** A microphone packet: size, type, rate, bits, stereo, samples. */
    static byte[] microphone(int type, int rate, int bits, int stereo, byte[] samples) {
        return start().u16(4 + samples.length).u16(type).u16(rate).u8(bits).u8(stereo).bytes(samples).build();
    }
}
