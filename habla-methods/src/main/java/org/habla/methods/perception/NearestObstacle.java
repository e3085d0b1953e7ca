package org.habla.methods.perception;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The {@code nearest} record of {@code nearest-distance}: the nearest thing a robot's range sensors see, and the
 * nearest straight ahead and straight behind.
 *
 * <pre>{@code
 * {"distanceM": 0.42, "angleRad": 0.52, "xM": 0.41, "yM": 0.27, "sensor": 2, "input": "scan",
 *  "valid": true, "aheadM": 0.42, "behindM": 5.0}
 * }</pre>
 *
 * {@code distanceM} is the range the sensor itself measured, from the sensor (a sonar transducer or infrared sensor
 * on the robot's body), not from the robot's centre nor from its outline: a Pioneer's transducers sit inside its
 * round outline, so its reading is more than the gap between the robot's edge and the obstacle. {@code xM},
 * {@code yM} and {@code angleRad} place the obstacle's point in the robot frame, from the robot's centre. When no reading is left
 * {@code valid} is false, {@code sensor} −1 and the distances are the sensors' longest reach.
 *
 * <p>Read from JSON (a record that came from a socket, a recording or a worker), a number the record lacks is NaN,
 * a missing {@code valid} counts as true, a missing {@code sensor} as −1 and a missing {@code input} as empty.
 */
public record NearestObstacle(double distanceM, double angleRad, double xM, double yM, int sensor, String input,
        boolean valid, double aheadM, double behindM) implements RecordForm {

    private static final String ROBOT_FRAME = "robot frame: from the robot's centre, x forward, y to the left";

    /** The fields of a nearest record. */
    public static final RecordLayout<NearestObstacle> LAYOUT = RecordLayout.of(NearestObstacle.class)
            .number("distanceM", NearestObstacle::distanceM).unit("m")
            .frame("from the sensor that read it: a sensor inside the robot's outline reads more than the gap from "
                    + "the robot's edge")
            .doc("the nearest valid reading; the longest reach when there is none")
            .number("angleRad", NearestObstacle::angleRad).unit("rad")
            .frame("robot frame: from the robot's centre, positive to the left").doc("the obstacle's bearing")
            .number("xM", NearestObstacle::xM).unit("m").frame(ROBOT_FRAME).doc("the obstacle's point, forward")
            .number("yM", NearestObstacle::yM).unit("m").frame(ROBOT_FRAME).doc("the obstacle's point, to the left")
            .longInteger("sensor", NearestObstacle::sensor).doc("the index of the sensor that read it, -1 for none")
            .text("input", NearestObstacle::input).doc("the input (scan, scan2, ...) whose scan it came from")
            .flag("valid", NearestObstacle::valid).doc("false when no sensor saw anything within its reach")
            .number("aheadM", NearestObstacle::aheadM).unit("m").frame("from the sensor that read it")
            .doc("the nearest reading within coneRad of straight ahead")
            .number("behindM", NearestObstacle::behindM).unit("m").frame("from the sensor that read it")
            .doc("the nearest reading within coneRad of straight behind")
            .build();

    public NearestObstacle {
        input = input == null ? "" : input;
    }

    @Override
    public RecordLayout<NearestObstacle> layout() {
        return LAYOUT;
    }

    /** The obstacle a nearest record carries: the form itself inside the daemon, else read from its JSON. */
    public static NearestObstacle fromRecord(RecordValue record) {
        return record.as(NearestObstacle.class, NearestObstacle::read);
    }

    private static NearestObstacle read(RecordValue r) {
        JsonNode valid = r.get("valid");
        JsonNode sensor = r.get("sensor");
        JsonNode input = r.get("input");
        return new NearestObstacle(number(r.get("distanceM")), number(r.get("angleRad")), number(r.get("xM")),
                number(r.get("yM")), sensor.isIntegralNumber() ? sensor.intValue() : -1,
                input.isTextual() ? input.textValue() : "", !valid.isBoolean() || valid.booleanValue(),
                number(r.get("aheadM")), number(r.get("behindM")));
    }

    /** A finite number, or NaN for anything else. */
    static double number(JsonNode n) {
        return n.isNumber() && Double.isFinite(n.doubleValue()) ? n.doubleValue() : Double.NaN;
    }
}
