package org.habla.methods.motion;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The detail of a {@code veto} notice of {@code movement-safety}: why a motion asked for was vetoed, for programs
 * (the notice's message says it for people). It reaches control clients as the notice's {@code detail} object,
 * whose fields the protocol documents: {@code askedMps}, {@code askedRadps}, {@code reason}, then the limit that
 * was crossed and what was measured.
 */
sealed interface VetoDetail extends RecordForm {

    /**
     * No fresh range data: no nearest record for {@code maxAgeMs}.
     *
     * @param askedMps   the forward speed asked for, within the top speeds
     * @param askedRadps the turn rate asked for, within the top speeds
     * @param maxAgeMs   how old the last nearest record may be
     * @param ageMs      how old the last nearest record is; null when none has come
     */
    record NoRangeData(double askedMps, double askedRadps, int maxAgeMs, Long ageMs) implements VetoDetail {

        static final RecordLayout<NoRangeData> LAYOUT = RecordLayout.of(NoRangeData.class)
                .number("askedMps", NoRangeData::askedMps).unit("m/s").doc("the forward speed asked for")
                .number("askedRadps", NoRangeData::askedRadps).unit("rad/s").doc("the turn rate asked for")
                .text("reason", d -> "no_range_data").doc("no_range_data: no nearest record for maxAgeMs")
                .longInteger("maxAgeMs", NoRangeData::maxAgeMs).unit("ms").doc("how old range data may be")
                .optionalLongInteger("ageMs", NoRangeData::ageMs).unit("ms")
                .doc("how old the last nearest record is; absent when none has come")
                .build();

        @Override
        public RecordLayout<NoRangeData> layout() {
            return LAYOUT;
        }
    }

    /**
     * An obstacle nearer than the stop distance in the direction asked for: ahead for a forward speed, behind for a
     * backward one.
     *
     * @param askedMps      the speed asked for, within the top speeds; not 0
     * @param askedRadps    the turn rate asked for, within the top speeds
     * @param obstacleM     how far the nearest obstacle in that direction is
     * @param stopDistanceM the distance within which motion towards an obstacle is vetoed
     */
    record Obstacle(double askedMps, double askedRadps, double obstacleM, double stopDistanceM) implements VetoDetail {

        static final RecordLayout<Obstacle> LAYOUT = RecordLayout.of(Obstacle.class)
                .number("askedMps", Obstacle::askedMps).unit("m/s").doc("the forward speed asked for")
                .number("askedRadps", Obstacle::askedRadps).unit("rad/s").doc("the turn rate asked for")
                .text("reason", d -> d.askedMps > 0 ? "obstacle_ahead" : "obstacle_behind")
                .doc("obstacle_ahead or obstacle_behind: the direction asked for")
                .number("obstacleM", Obstacle::obstacleM).unit("m").frame("from the robot, in the direction asked for")
                .doc("how far the nearest obstacle is")
                .number("stopDistanceM", Obstacle::stopDistanceM).unit("m")
                .doc("the distance within which motion towards an obstacle is vetoed")
                .build();

        @Override
        public RecordLayout<Obstacle> layout() {
            return LAYOUT;
        }
    }
}
