package org.habla.drivers.pioneer;

import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;

/**
 * Turns the SIPs of one session into readings in SI units: keeps odometry continuous across the
 * position roll-over and merges partial sonar updates into one full ring. One per session, used by the
 * session's reader only.
 */
final class SipTranslator {

    private final PioneerParams params;
    private final RollingPosition x = new RollingPosition();
    private final RollingPosition y = new RollingPosition();
    private final SonarRing sonar;
    private final SessionChannel odometry = new SessionChannel(PioneerChannels.ODOMETRY);
    private final SessionChannel battery = new SessionChannel(PioneerChannels.BATTERY);
    private final SessionChannel bumpers = new SessionChannel(PioneerChannels.BUMPERS);
    private final SessionChannel stall = new SessionChannel(PioneerChannels.STALL);
    private final SessionChannel status = new SessionChannel(PioneerChannels.STATUS);
    private final SessionChannel sonarRing = new SessionChannel(PioneerChannels.SONAR);
    private volatile RobotIdentity identity = RobotIdentity.UNKNOWN;
    private long ignoredPackets;

    SipTranslator(PioneerParams params) {
        this.params = params;
        this.sonar = new SonarRing(params.sonarCount(), params.maxRangeM());
    }

    /** Who the robot said it is in the handshake; shown in {@code status}. */
    void identity(RobotIdentity id) {
        identity = id;
    }

    /** The count of non-SIP packets the session has ignored, shown in {@code status}. */
    void ignoredPackets(long count) {
        ignoredPackets = count;
    }

    /** Emits every reading {@code sip} carries. */
    void translate(StandardSip sip, ReadingSink sink) {
        odometry.publish(sink, odometry(sip));
        battery.publish(sink, new NumberValue(batteryV(sip)));
        bumpers.publish(sink, RecordValue.of(BumperReading.of(sip, params.frontBumpers(), params.rearBumpers())));
        stall.publish(sink, RecordValue.of(StallReading.of(sip)));
        status.publish(sink, RecordValue.of(StatusReading.of(sip, identity, ignoredPackets)));
        if (!sip.sonar().isEmpty()) {
            for (StandardSip.SonarReading r : sip.sonar()) {
                if (!sonar.put(r.index(), r.range() * params.rangeConvFactor() / 1000.0)) {
                    sink.malformed("sonar index " + r.index() + " is not one of this robot's 0.." + (sonar.size() - 1));
                }
            }
            sonar.endUpdate();
            if (sonar.ready()) {
                sonarRing.publish(sink, VectorValue.wrap(sonar.snapshot()));
            }
        }
    }

    private RecordValue odometry(StandardSip sip) {
        double mPerUnit = params.distConvFactor() / 1000.0;
        double leftMps = sip.leftVel() * params.velConvFactor() / 1000.0;
        double rightMps = sip.rightVel() * params.velConvFactor() / 1000.0;
        double wRadps = sip.rotVelDdegps().isPresent()
                ? Math.toRadians(sip.rotVelDdegps().getAsInt() / 10.0)
                : (sip.rightVel() - sip.leftVel()) / 2.0 * params.velConvFactor() * params.diffConvFactor();
        return RecordValue.of(new OdometryReading(x.update(sip.xPos()) * mPerUnit, y.update(sip.yPos()) * mPerUnit,
                normalise(sip.thPos() * params.angleConvFactor()), (leftMps + rightMps) / 2.0, wRadps, leftMps,
                rightMps));
    }

    private static double batteryV(StandardSip sip) {
        int dv = sip.batteryX10().isPresent() && sip.batteryX10().getAsInt() > 0 ? sip.batteryX10().getAsInt() : sip.batteryDv();
        return dv / 10.0;
    }

    /** The angle in (-π, π]. */
    static double normalise(double rad) {
        double r = Math.IEEEremainder(rad, 2 * Math.PI);
        return r <= -Math.PI ? r + 2 * Math.PI : r;
    }
}
