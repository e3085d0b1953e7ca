package org.habla.drivers.tekkotsu;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.PayloadKind;

/** The names and descriptors of the {@code tekkotsu} driver's channels, with the ERS-7's metadata. */
final class TekkotsuChannels {

    static final String IR = "ir";
    static final String BUTTONS = "buttons";
    static final String JOINTS = "joints";
    static final String HEAD = "head";
    static final String HEAD_POSE = "head-pose";
    static final String ACCEL = "accel";
    static final String AUDIO = "audio";
    static final String CAMERA = "camera";
    static final String WALK = "walk";
    static final String SPEAKER = "speaker";

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    /**
     * Where the infrared sensors sit, in the body frame with the head straight (x forward, y left, m):
     * near and far in the nose, chest under the neck pointing forward and down. Approximate: measured
     * from drawings, not from Sony's tables.
     */
    private static final double[][] IR_POSES = {{0.19, 0, 0, 0}, {0.19, 0, 0, 0}, {0.12, 0, 0, -Math.toRadians(60)}};

    private TekkotsuChannels() {
    }

    /** The readings of the World State Serializer. */
    static List<ChannelDescriptor> worldState() {
        return List.of(
                ChannelDescriptor.reading(IR, PayloadKind.VECTOR, "m").withMetadata(irMetadata()),
                ChannelDescriptor.reading(BUTTONS, PayloadKind.RECORD, "").withMetadata(buttonMetadata()),
                ChannelDescriptor.reading(JOINTS, PayloadKind.VECTOR, "rad").withMetadata(names(Ers7.JOINT_NAMES)),
                ChannelDescriptor.reading(HEAD_POSE, PayloadKind.RECORD, "rad").withMetadata(headLimits()),
                ChannelDescriptor.reading(ACCEL, PayloadKind.VECTOR, "m/s^2").withMetadata(
                        names(List.of("backward", "left", "down"))));
    }

    static ChannelDescriptor microphone() {
        ObjectNode m = JSON.objectNode();
        m.put("sampleRateHz", 16_000).put("channels", 2).put("bitsPerSample", 16);
        return ChannelDescriptor.reading(AUDIO, PayloadKind.AUDIO, "").withMetadata(m);
    }

    static ChannelDescriptor camera(int skip, double heightM) {
        ObjectNode m = JSON.objectNode();
        m.put("hfovRad", Ers7.CAMERA_HFOV_RAD).put("vfovRad", Ers7.CAMERA_VFOV_RAD)
                .put("width", Ers7.CAMERA_WIDTH_BY_SKIP[skip]).put("height", Ers7.CAMERA_HEIGHT_BY_SKIP[skip])
                .put("heightM", heightM).put("mount", "head");
        return ChannelDescriptor.reading(CAMERA, PayloadKind.IMAGE, "").withMetadata(m);
    }

    static ChannelDescriptor walk(TekkotsuParams p) {
        ObjectNode m = JSON.objectNode();
        m.put("maxForwardMps", p.maxForwardMps()).put("maxReverseMps", p.maxReverseMps())
                .put("maxStrafeMps", p.maxStrafeMps()).put("maxRotateRadps", p.maxRotateRadps());
        m.set("names", JSON.arrayNode().add("forwardMps").add("strafeMps").add("rotateRadps"));
        return ChannelDescriptor.command(WALK, PayloadKind.VECTOR, "m/s, rad/s", true).withMetadata(m);
    }

    static ChannelDescriptor headCommand() {
        ObjectNode m = headLimits();
        m.set("names", JSON.arrayNode().add("tiltRad").add("panRad").add("nodRad"));
        return ChannelDescriptor.command(HEAD, PayloadKind.VECTOR, "rad", false).withMetadata(m);
    }

    static ChannelDescriptor speaker(int rateHz) {
        ObjectNode m = JSON.objectNode();
        m.put("sampleRateHz", rateHz).put("channels", 1).put("bitsPerSample", 16);
        return ChannelDescriptor.command(SPEAKER, PayloadKind.AUDIO, "", false).withMetadata(m);
    }

    private static ObjectNode irMetadata() {
        ObjectNode m = JSON.objectNode();
        ArrayNode poses = m.putArray("poses");
        for (int i = 0; i < IR_POSES.length; i++) {
            ObjectNode pose = poses.addObject();
            pose.put("name", Ers7.IR_NAMES.get(i)).put("xM", IR_POSES[i][0]).put("yM", IR_POSES[i][1])
                    .put("thetaRad", IR_POSES[i][2]).put("pitchRad", IR_POSES[i][3])
                    .put("mount", i == Ers7.CHEST_IR ? "body" : "head")
                    .put("minRangeM", Ers7.IR_MIN_M[i]).put("maxRangeM", Ers7.IR_MAX_M[i]);
        }
        m.put("minRangeM", 0.05).put("maxRangeM", 1.5);
        m.set("names", names(Ers7.IR_NAMES).get("names"));
        return m;
    }

    private static ObjectNode buttonMetadata() {
        ObjectNode m = names(Ers7.BUTTON_NAMES);
        m.set("tekkotsuNames", names(Ers7.TEKKOTSU_BUTTON_NAMES).get("names"));
        return m;
    }

    private static ObjectNode headLimits() {
        ObjectNode m = JSON.objectNode();
        String[] joints = {"tilt", "pan", "nod"};
        for (int i = 0; i < 3; i++) {
            m.put(joints[i] + "MinRad", Math.toRadians(Ers7.HEAD_MIN_DEG[i]));
            m.put(joints[i] + "MaxRad", Math.toRadians(Ers7.HEAD_MAX_DEG[i]));
        }
        return m;
    }

    private static ObjectNode names(List<String> names) {
        ObjectNode m = JSON.objectNode();
        ArrayNode a = m.putArray("names");
        names.forEach(a::add);
        return m;
    }
}
