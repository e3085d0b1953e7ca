package org.habla.sim.aibo;

import org.habla.sim.world.Pose2;

/**
 * Where the simulated ERS-7's head sensors are, from the body's pose on the floor and the head joints.
 * The body is a disc of {@link #BODY_RADIUS_M}; the neck sits {@link #NECK_FORWARD_M} ahead of its
 * centre and the nose (camera, near and far infrared) {@link #HEAD_LENGTH_M} further along the pan
 * direction, at {@link #NOSE_HEIGHT_M}; it pitches by tilt + nod. The chest infrared looks forward and
 * down from under the neck. Approximate sizes of a standing ERS-7, not Sony's drawings.
 */
public final class Ers7Geometry {

    public static final double BODY_RADIUS_M = 0.15;
    public static final double NECK_FORWARD_M = 0.08;
    public static final double HEAD_LENGTH_M = 0.07;
    /** The camera's height when standing: the tekkotsu driver's {@code cameraHeightM} default. */
    public static final double NOSE_HEIGHT_M = 0.2;
    public static final double CHEST_FORWARD_M = 0.12;
    public static final double CHEST_HEIGHT_M = 0.12;
    public static final double CHEST_PITCH_RAD = Math.toRadians(-60);
    /** The arena's walls are this tall for the camera and the infrared. */
    public static final double WALL_HEIGHT_M = 0.5;

    /** A sensor's place and direction: position in metres, yaw (world frame, CCW) and pitch (+ up). */
    public record Ray(double xM, double yM, double zM, double yawRad, double pitchRad) {
    }

    private Ers7Geometry() {
    }

    /** The nose: where the camera and the head's infrared sensors look from. */
    public static Ray nose(Pose2 body, Ers7Body.HeadPose head) {
        Pose2 neck = body.moved(NECK_FORWARD_M, 0, 0);
        double yaw = body.thetaRad() + head.panRad();
        return new Ray(neck.xM() + HEAD_LENGTH_M * Math.cos(yaw), neck.yM() + HEAD_LENGTH_M * Math.sin(yaw),
                NOSE_HEIGHT_M, yaw, head.tiltRad() + head.nodRad());
    }

    /** The chest infrared sensor. */
    public static Ray chest(Pose2 body) {
        Pose2 p = body.moved(CHEST_FORWARD_M, 0, 0);
        return new Ray(p.xM(), p.yM(), CHEST_HEIGHT_M, body.thetaRad(), CHEST_PITCH_RAD);
    }
}
