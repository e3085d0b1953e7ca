package org.habla.drivers.pioneer;

import java.util.List;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/**
 * The params of a {@code pioneer} interface: the session's behaviour, the robot's conversion factors
 * and its geometry. Every default is the Pioneer 2 DX's (ARIA's {@code p2dx} parameter file), except the
 * speed limits, which are the simulated P2DX's (its physical top speed is not documented).
 */
public record PioneerParams(
        @Param(value = "Send ENABLE 1 after OPEN, so the motors obey motion commands", defaultValue = "true")
        Boolean enableMotors,
        @Param(value = "Period of the PULSE keep-alive, well inside the robot's 2 s watchdog", unit = "ms",
                defaultValue = "500")
        Integer keepAlivePeriodMs,
        @Param(value = "Millimetres per SIP position unit (DistConvFactor)", unit = "mm", defaultValue = "0.840")
        Double distConvFactor,
        @Param(value = "Radians per SIP heading unit (AngleConvFactor; 2π/4096)", unit = "rad",
                defaultValue = "0.001534")
        Double angleConvFactor,
        @Param(value = "mm/s per SIP wheel-velocity unit (VelConvFactor)", unit = "mm/s", defaultValue = "1.0")
        Double velConvFactor,
        @Param(value = "Millimetres per sonar range unit (RangeConvFactor; 1.0 on ARCOS robots)", unit = "mm",
                defaultValue = "0.268")
        Double rangeConvFactor,
        @Param(value = "rad/s of rotation per mm/s of half the wheel-speed difference, used when the SIP has no ROTVEL"
                + " (DiffConvFactor)", unit = "rad/mm", defaultValue = "0.0056")
        Double diffConvFactor,
        @Param(value = "Highest translational speed a motion command may ask for", unit = "m/s", defaultValue = "0.75")
        Double maxVelMps,
        @Param(value = "Highest rotational speed a motion command may ask for", unit = "rad/s", defaultValue = "1.74")
        Double maxRotVelRadps,
        @Param(value = "Robot radius for obstacle checks", unit = "m", defaultValue = "0.25")
        Double radiusM,
        @Param(value = "Robot width", unit = "m", defaultValue = "0.425")
        Double widthM,
        @Param(value = "Robot length", unit = "m", defaultValue = "0.511")
        Double lengthM,
        @Param(value = "Front bumper switches reported in the SIP", defaultValue = "5")
        Integer frontBumpers,
        @Param(value = "Rear bumper switches reported in the SIP", defaultValue = "5")
        Integer rearBumpers,
        @Param(value = "Shortest range a sonar reports", unit = "m", defaultValue = "0.1")
        Double minRangeM,
        @Param(value = "Longest range a sonar reports (also its reading when nothing is in view)", unit = "m",
                defaultValue = "5.0")
        Double maxRangeM,
        @Param(value = "Full width of a sonar beam", unit = "rad", defaultValue = "0.5235987755982988")
        Double beamWidthRad,
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
        enableMotors = ParamDefaults.or(PioneerParams.class, "enableMotors", enableMotors);
        keepAlivePeriodMs = ParamDefaults.or(PioneerParams.class, "keepAlivePeriodMs", keepAlivePeriodMs);
        distConvFactor = positive("distConvFactor", distConvFactor);
        angleConvFactor = positive("angleConvFactor", angleConvFactor);
        velConvFactor = positive("velConvFactor", velConvFactor);
        rangeConvFactor = positive("rangeConvFactor", rangeConvFactor);
        diffConvFactor = positive("diffConvFactor", diffConvFactor);
        maxVelMps = positive("maxVelMps", maxVelMps);
        maxRotVelRadps = positive("maxRotVelRadps", maxRotVelRadps);
        radiusM = positive("radiusM", radiusM);
        widthM = positive("widthM", widthM);
        lengthM = positive("lengthM", lengthM);
        frontBumpers = ParamDefaults.or(PioneerParams.class, "frontBumpers", frontBumpers);
        rearBumpers = ParamDefaults.or(PioneerParams.class, "rearBumpers", rearBumpers);
        minRangeM = ParamDefaults.or(PioneerParams.class, "minRangeM", minRangeM);
        maxRangeM = positive("maxRangeM", maxRangeM);
        beamWidthRad = positive("beamWidthRad", beamWidthRad);
        sonarPoses = sonarPoses == null ? P2DX_SONAR_POSES : List.copyOf(sonarPoses);

        if (keepAlivePeriodMs < 50 || keepAlivePeriodMs > 1500) {
            throw new IllegalArgumentException("keepAlivePeriodMs must be in 50..1500 (inside the 2 s watchdog), was "
                    + keepAlivePeriodMs);
        }
        if (frontBumpers < 0 || frontBumpers > 7) {
            throw new IllegalArgumentException("frontBumpers must be in 0..7, was " + frontBumpers);
        }
        if (rearBumpers < 0 || rearBumpers > 7) {
            throw new IllegalArgumentException("rearBumpers must be in 0..7, was " + rearBumpers);
        }
        if (!(minRangeM >= 0 && minRangeM < maxRangeM)) {
            throw new IllegalArgumentException("minRangeM must be in [0, maxRangeM), was " + minRangeM);
        }
        if (maxVelMps * 1000 > Short.MAX_VALUE) {
            throw new IllegalArgumentException("maxVelMps must be at most 32.767, was " + maxVelMps);
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
        return new PioneerParams(null, null, null, null, null, null, null, null, null, null, null, null, null, null,
                null, null, null, null);
    }

    /** Sonar transducers on the robot. */
    public int sonarCount() {
        return sonarPoses.size();
    }

    private static Double positive(String name, Double value) {
        double v = ParamDefaults.or(PioneerParams.class, name, value);
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a positive number, was " + value);
        }
        return v;
    }
}
