package org.habla.drivers.pioneer;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code odometry} reading of a Pioneer: its pose by dead reckoning, in the odometry frame its controller keeps
 * since it was switched on, and its speeds, from one SIP.
 */
record OdometryReading(double xM, double yM, double thetaRad, double vMps, double wRadps, double leftMps,
        double rightMps) implements RecordForm {

    private static final String FRAME = "odometry frame: where the controller started, x along its first heading";

    static final RecordLayout<OdometryReading> LAYOUT = RecordLayout.of(OdometryReading.class)
            .number("xM", OdometryReading::xM).unit("m").frame(FRAME).doc("position, forward of the start")
            .number("yM", OdometryReading::yM).unit("m").frame(FRAME).doc("position, left of the start")
            .number("thetaRad", OdometryReading::thetaRad).unit("rad").frame("counter-clockwise from x, within (-π, π]")
            .doc("heading")
            .number("vMps", OdometryReading::vMps).unit("m/s").doc("forward speed, the mean of the wheels'")
            .number("wRadps", OdometryReading::wRadps).unit("rad/s").doc("turn rate, counter-clockwise")
            .number("leftMps", OdometryReading::leftMps).unit("m/s").doc("the left wheel's speed")
            .number("rightMps", OdometryReading::rightMps).unit("m/s").doc("the right wheel's speed")
            .build();

    @Override
    public RecordLayout<OdometryReading> layout() {
        return LAYOUT;
    }
}
