package org.habla.sim.room;

/**
 * How to run the simulated room.
 *
 * @param brokerHost  the MQTT broker's host
 * @param brokerPort  the MQTT broker's port
 * @param baseTopic   the devices' base topic, as Zigbee2MQTT's {@code base_topic}
 * @param speed       sim time runs this many times faster than real time
 * @param seed        the seed of the person's walk and the clouds
 * @param daySeconds  the length of a simulated day, in sim seconds
 * @param dayPhase    where in the day the simulation starts: 0 sunrise, 0.25 noon, 0.5 sunset, 0.75 midnight
 * @param reportS     how often the motion sensors report illuminance when nothing changes, in sim seconds
 * @param teacherS    how long the teacher stays and rewards the lamps, in sim seconds (0: no teacher)
 */
public record RoomSimOptions(String brokerHost, int brokerPort, String baseTopic, double speed, long seed,
        double daySeconds, double dayPhase, double reportS, double teacherS) {

    public static final String DEFAULT_BASE_TOPIC = "zigbee2mqtt";
    /** The topic the simulator publishes its ground truth on (not a device). */
    public static final String TRUTH_TOPIC = "habla-sim/room/truth";
    /** The topic the simulator publishes every reward the teacher gives on, with what it judged. */
    public static final String TEACHER_TOPIC = "habla-sim/room/teacher";
    /** The topic a scenario sends the teacher in or away on: {@code {"teacher": true|false}}. */
    public static final String CONTROL_TOPIC = "habla-sim/room/control";

    public RoomSimOptions {
        if (!(speed >= 1)) {
            throw new IllegalArgumentException("--speed must be at least 1, was " + speed);
        }
        if (!(daySeconds >= 10)) {
            throw new IllegalArgumentException("--day must be at least 10 sim seconds, was " + daySeconds);
        }
        if (!(reportS > 0)) {
            throw new IllegalArgumentException("--report must be positive, was " + reportS);
        }
        if (!(teacherS >= 0)) {
            throw new IllegalArgumentException("--teacher must be at least 0 s, was " + teacherS);
        }
        if (brokerPort < 1 || brokerPort > 65_535) {
            throw new IllegalArgumentException("the broker port must be in 1..65535, was " + brokerPort);
        }
    }
}
