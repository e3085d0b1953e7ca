package org.habla.drivers.pioneer;

/**
 * Where one sonar transducer sits on the robot and where it points: x forward, y left, the angle
 * counter-clockwise from straight ahead.
 */
public record SonarPose(double xM, double yM, double thetaRad) {

    public SonarPose {
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(thetaRad)) {
            throw new IllegalArgumentException("sonarPoses: a pose needs finite xM, yM and thetaRad");
        }
    }

    /** A pose given in millimetres and degrees, as the robot's parameter files list them. */
    static SonarPose ofMmDeg(double xMm, double yMm, double thetaDeg) {
        return new SonarPose(xMm / 1000.0, yMm / 1000.0, Math.toRadians(thetaDeg));
    }
}
