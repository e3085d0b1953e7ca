package org.habla.drivers.pioneer;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The params of a {@code pioneer} interface: the session's behaviour, the robot's conversion factors
 * and its geometry. Every default is the Pioneer 2 DX's (ARIA's {@code p2dx} parameter file), except the
 * speed limits, which are the simulated P2DX's (its physical top speed is not documented).
 */
public record PioneerParams(
        @Param(value = "Send ENABLE 1 after OPEN, so the motors obey motion commands", defaultValue = "true")
        boolean enableMotors,
        @Param(value = "Period of the PULSE keep-alive, well inside the robot's 2 s watchdog", unit = "ms",
                defaultValue = "500", min = 50, max = 1500)
        int keepAlivePeriodMs,
        @Param(value = "Millimetres per SIP position unit (DistConvFactor)", unit = "mm", defaultValue = "0.840",
                greaterThan = 0)
        double distConvFactor,
        @Param(value = "Radians per SIP heading unit (AngleConvFactor; 2π/4096)", unit = "rad",
                defaultValue = "0.001534", greaterThan = 0)
        double angleConvFactor,
        @Param(value = "mm/s per SIP wheel-velocity unit (VelConvFactor)", unit = "mm/s", defaultValue = "1.0",
                greaterThan = 0)
        double velConvFactor,
        @Param(value = "Millimetres per sonar range unit (RangeConvFactor; 1.0 on ARCOS robots)", unit = "mm",
                defaultValue = "0.268", greaterThan = 0)
        double rangeConvFactor,
        @Param(value = "rad/s of rotation per mm/s of half the wheel-speed difference, used when the SIP has no ROTVEL"
                + " (DiffConvFactor)", unit = "rad/mm", defaultValue = "0.0056", greaterThan = 0)
        double diffConvFactor,
        @Param(value = "Highest translational speed a motion command may ask for", unit = "m/s", defaultValue = "0.75",
                greaterThan = 0, max = 32.767)
        double maxVelMps,
        @Param(value = "Highest rotational speed a motion command may ask for", unit = "rad/s", defaultValue = "1.74",
                greaterThan = 0)
        double maxRotVelRadps,
        @Param(value = "Robot radius for obstacle checks", unit = "m", defaultValue = "0.25", greaterThan = 0)
        double radiusM,
        @Param(value = "Robot width", unit = "m", defaultValue = "0.425", greaterThan = 0)
        double widthM,
        @Param(value = "Robot length", unit = "m", defaultValue = "0.511", greaterThan = 0)
        double lengthM,
        @Param(value = "Front bumper switches reported in the SIP", defaultValue = "5", min = 0, max = 7)
        int frontBumpers,
        @Param(value = "Rear bumper switches reported in the SIP", defaultValue = "5", min = 0, max = 7)
        int rearBumpers,
        @Param(value = "Shortest range a sonar reports", unit = "m", defaultValue = "0.1", min = 0)
        double minRangeM,
        @Param(value = "Longest range a sonar reports (also its reading when nothing is in view)", unit = "m",
                defaultValue = "5.0", greaterThan = 0)
        double maxRangeM,
        @Param(value = "Full width of a sonar beam", unit = "rad", defaultValue = "0.5235987755982988", greaterThan = 0)
        double beamWidthRad,
        @Param(value = "Sonar transducer poses [{xM, yM, thetaRad}], one per transducer in index order",
                unit = "m, rad", defaultNote = "the 16 P2DX poses")
        List<SonarPose> sonarPoses) {

    /** The Pioneer 2 DX sonar ring: front 0–7 from the left side round to the right, rear 8–15 back round. */
    public static final List<SonarPose> P2DX_SONAR_POSES = List.of(
            SonarPose.ofMmDeg(69, 136, 90), SonarPose.ofMmDeg(114, 119, 50), SonarPose.ofMmDeg(148, 78, 30),
            SonarPose.ofMmDeg(166, 27, 10), SonarPose.ofMmDeg(166, -27, -10), SonarPose.ofMmDeg(148, -78, -30),
            SonarPose.ofMmDeg(114, -119, -50), SonarPose.ofMmDeg(69, -136, -90), SonarPose.ofMmDeg(-157, -136, -90),
            SonarPose.ofMmDeg(-203, -119, -130), SonarPose.ofMmDeg(-237, -78, -150), SonarPose.ofMmDeg(-255, -27, -170),
            SonarPose.ofMmDeg(-255, 27, 170), SonarPose.ofMmDeg(-237, 78, 150), SonarPose.ofMmDeg(-203, 119, 130),
            SonarPose.ofMmDeg(-157, 136, 90));

    /** Sonar indices a SIP can carry. */
    public static final int MAX_SONARS = 32;

    public PioneerParams {
        sonarPoses = sonarPoses == null ? P2DX_SONAR_POSES : List.copyOf(sonarPoses);

        if (!(minRangeM < maxRangeM)) {
            throw new IllegalArgumentException("minRangeM must be below maxRangeM, was " + minRangeM);
        }
        if (Math.toDegrees(maxRotVelRadps) > Short.MAX_VALUE) {
            throw new IllegalArgumentException("maxRotVelRadps is too large: " + maxRotVelRadps);
        }
        if (sonarPoses.isEmpty() || sonarPoses.size() > MAX_SONARS) {
            throw new IllegalArgumentException("sonarPoses must list 1.." + MAX_SONARS + " poses, has " + sonarPoses.size());
        }
    }

    /** Every parameter at its default. */
    public static PioneerParams defaults() {
        return ParamsJson.defaults(PioneerParams.class);
    }

    /** Sonar transducers on the robot. */
    public int sonarCount() {
        return sonarPoses.size();
    }
}
