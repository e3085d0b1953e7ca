package org.habla.drivers.tekkotsu;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;

/**
 * The session on the World State Serializer (port 10031): decodes each ERS-7 packet into the
 * {@code joints}, {@code head}, {@code ir}, {@code accel} and {@code buttons} readings.
 *
 * <p>A packet from another model or with counts that do not match the ERS-7 tables is framed by
 * its own counts, reported as malformed and skipped. Garbage is reported once and skipped up to the
 * next {@code "ERS-"}. A stream in the pre-4.0 layout (a timestamp, then the value 18) cannot be
 * decoded at all and ends the link with a message that says so.
 */
final class WorldStateSession implements LinkSession {

    private final SessionChannel accelChannel = new SessionChannel(TekkotsuChannels.ACCEL);
    private final SessionChannel buttonsChannel = new SessionChannel(TekkotsuChannels.BUTTONS);
    private final SessionChannel headPoseChannel = new SessionChannel(TekkotsuChannels.HEAD_POSE);
    private final SessionChannel irChannel = new SessionChannel(TekkotsuChannels.IR);
    private final SessionChannel jointsChannel = new SessionChannel(TekkotsuChannels.JOINTS);

    /** How far to look for the next packet start in garbage before giving up on the stream. */
    static final int RESYNC_LIMIT_BYTES = 4_096;

    private boolean decodedAny;
    private boolean outOfStep;
    private boolean infoSent;
    private long batteryPercent = -1;

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        WireInput wire = new WireInput(in);
        if (outOfStep) {
            wire.skipPast(WorldStatePacket.MAGIC, RESYNC_LIMIT_BYTES, "World State packet");
        } else {
            byte[] start = wire.bytes(4, "World State packet start");
            if (!Arrays.equals(start, WorldStatePacket.MAGIC)) {
                if (!decodedAny) {
                    rejectOldLayout(start, wire);
                }
                outOfStep = true;
                sink.malformed("World State stream out of step: expected a model name 'ERS-…', got bytes "
                        + HexFormat.ofDelimiter(" ").formatHex(start) + "; skipping to the next packet");
                return;
            }
        }
        WorldStatePacket packet;
        try {
            packet = WorldStatePacket.readAfterMagic(wire);
        } catch (WireInput.MalformedFieldException e) {
            outOfStep = true;
            sink.malformed("World State packet: " + e.getMessage() + "; skipping to the next packet");
            return;
        }
        outOfStep = false;
        Optional<String> mismatch = packet.ers7Mismatch();
        if (mismatch.isPresent()) {
            sink.malformed(mismatch.get());
            return;
        }
        decodedAny = true;
        reportInfo(packet, sink);
        publish(packet, sink);
    }

    /** The model once, and the battery whenever its whole percentage changes (the robot updates it rarely). */
    private void reportInfo(WorldStatePacket packet, ReadingSink sink) {
        float[] s = packet.sensors();
        long percent = Math.round(s[Ers7.POWER_REMAIN] * 100.0);
        if (infoSent && percent == batteryPercent) {
            return;
        }
        ObjectNode info = JsonNodeFactory.instance.objectNode();
        if (!infoSent) {
            info.put("model", packet.model());
            info.put("worldStateLayout", "Tekkotsu 4.0+");
            infoSent = true;
        }
        batteryPercent = percent;
        info.put("batteryPercent", percent);
        info.put("batteryVoltageV", (double) s[Ers7.POWER_VOLTAGE]);
        sink.robotInfo(info);
    }

    /** The pre-4.0 layout starts with a timestamp and then NumPIDJoints = 18 (bytes 12 00 00 00). */
    private static void rejectOldLayout(byte[] start, WireInput wire) throws IOException {
        long next = wire.u32("World State packet start");
        if (next == Ers7.NUM_PID_JOINTS) {
            throw new IOException("the World State stream has the pre-4.0 Tekkotsu layout (a timestamp, then 18 "
                    + "joints, no model name); the tekkotsu driver decodes Tekkotsu 4.0 and later only");
        }
    }

    void publish(WorldStatePacket p, ReadingSink sink) {
        float[] out = p.outputs();
        double[] joints = new double[Ers7.NUM_PID_JOINTS];
        for (int i = 0; i < joints.length; i++) {
            joints[i] = out[i];
        }
        jointsChannel.publish(sink, VectorValue.wrap(joints));
        headPoseChannel.publish(sink, RecordValue.of(
                new HeadPoseReading(out[Ers7.HEAD_TILT], out[Ers7.HEAD_PAN], out[Ers7.HEAD_NOD])));
        float[] s = p.sensors();
        irChannel.publish(sink, VectorValue.of(
                s[Ers7.NEAR_IR] / 1000.0, s[Ers7.FAR_IR] / 1000.0, s[Ers7.CHEST_IR] / 1000.0));
        accelChannel.publish(sink, VectorValue.of(s[Ers7.B_ACCEL], s[Ers7.L_ACCEL], s[Ers7.D_ACCEL]));
        Map<String, Double> buttons = new LinkedHashMap<>();
        float[] b = p.buttons();
        for (int i = 0; i < b.length; i++) {
            buttons.put(Ers7.BUTTON_NAMES.get(i), unit(b[i]));
        }
        buttonsChannel.publish(sink, RecordValue.of(new ButtonsReading(buttons)));
    }

    /** A button value clamped to 0..1; NaN reads as not pressed. */
    private static double unit(float v) {
        return v > 0 ? Math.min(1.0, v) : 0.0;
    }
}
