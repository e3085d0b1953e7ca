package org.habla.sim.pioneer;

import java.util.List;
import org.habla.sim.world.Body;

/**
 * The facts of a Pioneer 2 DX the simulator reproduces: its conversion factors (ARIA's {@code p2dx} parameters),
 * its body (radius, speeds and accelerations of the simulated P2 series) and its 16-sonar ring.
 */
final class P2dx {

    static final String ROBOT_CLASS = "Pioneer";
    static final String SUBCLASS = "p2dx";

    /** Millimetres per SIP position unit. */
    static final double DIST_CONV_MM = 0.840;
    /** Radians per SIP heading unit: 4096 units per revolution. */
    static final double ANGLE_CONV_RAD = 2 * Math.PI / 4096;
    /** Millimetres per sonar range unit. */
    static final double RANGE_CONV_MM = 0.268;
    /** rad/s of rotation per mm/s of half the wheel-speed difference. */
    static final double DIFF_CONV = 0.0056;
    /** VEL2 wheel-speed byte × this = mm/s. */
    static final int VEL2_DIVISOR = 20;

    static final double RADIUS_M = 0.25;
    static final double MAX_VEL_MPS = 0.75;
    static final double MAX_ROT_VEL_RADPS = 1.74;
    static final double ACCEL_MPS2 = 0.3;
    static final double DECEL_MPS2 = 0.6;
    static final double ROT_ACCEL_RADPS2 = 1.74;

    static final double SONAR_MIN_RANGE_M = 0.1;
    static final double SONAR_MAX_RANGE_M = 5.0;
    /** Full width of a sonar beam. */
    static final double SONAR_BEAM_RAD = Math.toRadians(30);
    /** Each ring fires one transducer this often, so a transducer is read every 8 × 40 ms. */
    static final double SONAR_FIRE_PERIOD_S = 0.040;
    /** Standard SIP period. */
    static final double SIP_PERIOD_S = 0.100;
    /** Silence after which the controller stops the robot. */
    static final double WATCHDOG_S = 2.0;
    /** Battery voltage reported, 0.1 V. */
    static final int BATTERY_DV = 130;
    static final int FRONT_BUMPERS = 5;
    static final int REAR_BUMPERS = 5;

    /** One sonar transducer: position on the robot (m) and the direction it faces (rad, + left). */
    record Transducer(double xM, double yM, double thetaRad) {
        static Transducer mmDeg(double x, double y, double deg) {
            return new Transducer(x / 1000, y / 1000, Math.toRadians(deg));
        }
    }

    /** Front ring 0–7 from the left side round to the right, rear ring 8–15 from the right round to the left. */
    static final List<Transducer> SONARS = List.of(
            Transducer.mmDeg(69, 136, 90), Transducer.mmDeg(114, 119, 50), Transducer.mmDeg(148, 78, 30),
            Transducer.mmDeg(166, 27, 10), Transducer.mmDeg(166, -27, -10), Transducer.mmDeg(148, -78, -30),
            Transducer.mmDeg(114, -119, -50), Transducer.mmDeg(69, -136, -90), Transducer.mmDeg(-157, -136, -90),
            Transducer.mmDeg(-203, -119, -130), Transducer.mmDeg(-237, -78, -150), Transducer.mmDeg(-255, -27, -170),
            Transducer.mmDeg(-255, 27, 170), Transducer.mmDeg(-237, 78, 150), Transducer.mmDeg(-203, 119, 130),
            Transducer.mmDeg(-157, 136, 90));

    static Body.Limits bodyLimits() {
        return new Body.Limits(RADIUS_M, MAX_VEL_MPS, MAX_ROT_VEL_RADPS, ACCEL_MPS2, ROT_ACCEL_RADPS2, DECEL_MPS2,
                ROT_ACCEL_RADPS2);
    }

    private P2dx() {
    }
}
