package org.habla.drivers.tekkotsu;

import java.util.List;

/**
 * The Sony ERS-7's tables as Tekkotsu numbers them (Tekkotsu {@code ERS7Info}): counts, the order of
 * joints, sensors and buttons in the World State stream, joint ranges and the camera's field of view.
 */
final class Ers7 {

    static final String MODEL = "ERS-7";
    static final int NUM_OUTPUTS = 47;
    static final int NUM_SENSORS = 11;
    static final int NUM_BUTTONS = 10;
    static final int NUM_PID_JOINTS = 18;

    /** The 18 PID joints, in output order (outputs 0..17). */
    static final List<String> JOINT_NAMES = List.of(
            "LFr:rotor", "LFr:elvtr", "LFr:knee", "RFr:rotor", "RFr:elvtr", "RFr:knee",
            "LBk:rotor", "LBk:elvtr", "LBk:knee", "RBk:rotor", "RBk:elvtr", "RBk:knee",
            "NECK:tilt", "NECK:pan", "NECK:nod", "TAIL:tilt", "TAIL:pan", "MOUTH");

    static final int HEAD_TILT = 12;
    static final int HEAD_PAN = 13;
    static final int HEAD_NOD = 14;

    /** Head joint limits in degrees, from {@code outputRanges}: tilt, pan, nod. */
    static final double[] HEAD_MIN_DEG = {-75, -88, -15};
    static final double[] HEAD_MAX_DEG = {0, 88, 45};

    /** HABLA's names of the 10 buttons, in Tekkotsu's order (LFrPaw ... WirelessSw). */
    static final List<String> BUTTON_NAMES = List.of(
            "leftFrontPaw", "rightFrontPaw", "leftBackPaw", "rightBackPaw", "chin",
            "headTouch", "backFront", "backMiddle", "backRear", "wirelessSwitch");

    /** Tekkotsu's own names of the buttons, same order, for the docs and messages. */
    static final List<String> TEKKOTSU_BUTTON_NAMES = List.of(
            "LFrPaw", "RFrPaw", "LBkPaw", "RBkPaw", "ChinBut",
            "HeadBut", "FrontBackBut", "MiddleBackBut", "RearBackBut", "WirelessSw");

    static final int NEAR_IR = 0;
    static final int FAR_IR = 1;
    static final int CHEST_IR = 2;
    static final int B_ACCEL = 3;
    static final int L_ACCEL = 4;
    static final int D_ACCEL = 5;
    static final int POWER_REMAIN = 6;
    static final int POWER_VOLTAGE = 9;

    /** The infrared sensors: name, range limits in metres. */
    static final List<String> IR_NAMES = List.of("near", "far", "chest");
    static final double[] IR_MIN_M = {0.05, 0.2, 0.1};
    static final double[] IR_MAX_M = {0.5, 1.5, 0.9};

    /** Camera field of view, 56.9° × 45.2°. */
    static final double CAMERA_HFOV_RAD = Math.toRadians(56.9);
    static final double CAMERA_VFOV_RAD = Math.toRadians(45.2);

    /** Image width at resolution skip 0..5 (layer 5..0); height is width × 10 / 13. */
    static final int[] CAMERA_WIDTH_BY_SKIP = {416, 208, 104, 52, 26, 13};
    static final int[] CAMERA_HEIGHT_BY_SKIP = {320, 160, 80, 40, 20, 10};

    /** Total size of one World State packet for the ERS-7: 374 bytes. */
    static final int WORLD_STATE_BYTES = MODEL.length() + 1 + 6 * 4
            + (NUM_OUTPUTS + NUM_SENSORS + NUM_BUTTONS + NUM_PID_JOINTS) * 4;

    private Ers7() {
    }
}
