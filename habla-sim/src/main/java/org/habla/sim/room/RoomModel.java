package org.habla.sim.room;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * The physics of the simulated room, stepped in sim time and free of any I/O: a row of zones, each with a motion
 * sensor, a light sensor and a dimmable lamp; a door out of the last zone; a person who stays in a zone for a
 * while, walks to a neighbouring one and now and then leaves through the door; daylight through the windows that
 * rises and falls over a simulated day, with passing clouds; the air's temperature and humidity.
 *
 * <pre>
 *   window ▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒▒
 *   │  desk (×1.0)  │  sofa (×0.6)  │  kitchen (×0.3)  ┊door┊ → out
 *   │   lamp ☼      │   lamp ☼      │   lamp ☼         │
 * </pre>
 *
 * A lamp at full brightness adds {@link #LAMP_LUX} to its own zone and a share to each neighbour; its power is
 * {@link #LAMP_WATTS} at full brightness, and the energy every lamp used is counted.
 */
public final class RoomModel {

    /** Illuminance a lamp at full brightness adds to its own zone. */
    public static final double LAMP_LUX = 400;
    /** The share of a lamp's light that reaches a neighbouring zone. */
    public static final double SPILL = 0.15;
    /** A lamp's power at full brightness, in watts (a bright LED bulb). */
    public static final double LAMP_WATTS = 10;
    /** Daylight at the brightest window at noon under a clear sky, in lux. */
    public static final double NOON_LUX = 900;
    /** A zone is dark for reading below this many lux: the teacher wants its lamp on if someone is there. */
    public static final double DARK_LUX = 200;
    /** How long a motion sensor keeps reporting occupancy after the last movement it saw (Zigbee2MQTT's timeout). */
    public static final double OCCUPANCY_TIMEOUT_S = 10;
    /**
     * How long after the person left a zone the teacher still counts it as theirs: a motion sensor keeps saying
     * occupied for {@link #OCCUPANCY_TIMEOUT_S}, and a lamp left on a few seconds for someone who just stepped
     * out is no fault.
     */
    public static final double LINGER_S = 15;
    /** How long the door stays open when the person passes. */
    public static final double DOOR_OPEN_S = 2;

    private final List<String> zones;
    private final double[] window;
    private final double daySeconds;
    private final double dayPhase;
    private final Random rng;
    private final double[] brightness;
    private final double[] energyWh;
    private final double[] lastMotionS;
    private final double[] leftS;
    private int personZone;
    private double leaveAtS;
    private double doorOpenUntilS = -1;
    private double clouds = 1;
    private double nowS;
    private double temperatureC = 21.0;
    private double humidityPct = 45.0;

    /**
     * @param zones      the zones in a row; the last one has the door
     * @param window     each zone's share of the daylight (1 at the window)
     * @param daySeconds the length of a simulated day in sim seconds
     * @param dayPhase   where in the day the simulation starts, 0..1 (0.25 is noon, 0.75 midnight)
     */
    public RoomModel(List<String> zones, double[] window, double daySeconds, double dayPhase, long seed) {
        if (zones.isEmpty() || zones.size() != window.length) {
            throw new IllegalArgumentException("every zone needs its window share");
        }
        this.zones = List.copyOf(zones);
        this.window = window.clone();
        this.daySeconds = daySeconds;
        this.dayPhase = dayPhase;
        this.rng = new Random(seed);
        this.brightness = new double[zones.size()];
        this.energyWh = new double[zones.size()];
        this.lastMotionS = new double[zones.size()];
        java.util.Arrays.fill(lastMotionS, -1e9);
        this.leftS = new double[zones.size()];
        java.util.Arrays.fill(leftS, -1e9);
        this.personZone = 0;
        this.leaveAtS = dwell();
        lastMotionS[0] = 0;
    }

    /** The built-in room: desk by the window, sofa, kitchen with the door. */
    public static RoomModel standard(double daySeconds, double dayPhase, long seed) {
        return new RoomModel(List.of("desk", "sofa", "kitchen"), new double[] {1.0, 0.6, 0.3}, daySeconds, dayPhase,
                seed);
    }

    public List<String> zones() {
        return zones;
    }

    public double nowS() {
        return nowS;
    }

    /** Advances the room by {@code dtS}: the person moves, sensors see, lamps use energy, clouds pass. */
    public void step(double dtS) {
        nowS += dtS;
        for (int z = 0; z < zones.size(); z++) {
            energyWh[z] += brightness[z] * LAMP_WATTS * dtS / 3600;
        }
        clouds = Math.max(0.5, Math.min(1, clouds + (rng.nextGaussian() * 0.02 + (0.85 - clouds) * 0.01) * dtS));
        if (nowS >= leaveAtS) {
            move();
        }
        if (personZone >= 0 && rng.nextDouble() < dtS / 6.0) {
            // Someone sitting still still moves now and then.
            lastMotionS[personZone] = nowS;
        }
        double warm = personZone >= 0 ? 0.002 : -0.001;
        temperatureC = Math.max(18, Math.min(26, temperatureC + (warm + rng.nextGaussian() * 0.002) * dtS));
        humidityPct = Math.max(30, Math.min(60, humidityPct + rng.nextGaussian() * 0.02 * dtS));
    }

    private void move() {
        int last = zones.size() - 1;
        if (personZone >= 0) {
            leftS[personZone] = nowS;
        }
        if (personZone < 0) {
            personZone = last;
            openDoor();
        } else if (personZone == last && rng.nextDouble() < 0.35) {
            personZone = -1;
            openDoor();
            leaveAtS = nowS + 20 + rng.nextDouble() * 40;
            return;
        } else {
            int step = personZone == 0 ? 1 : personZone == last ? -1 : rng.nextBoolean() ? 1 : -1;
            personZone += step;
        }
        lastMotionS[personZone] = nowS;
        leaveAtS = nowS + dwell();
    }

    private void openDoor() {
        doorOpenUntilS = nowS + DOOR_OPEN_S;
    }

    private double dwell() {
        return 15 + rng.nextDouble() * 35;
    }

    /** The person's zone, or -1 while out of the room. */
    public int personZone() {
        return personZone;
    }

    /** Whether zone {@code z}'s motion sensor reports occupancy now. */
    public boolean motion(int z) {
        return nowS - lastMotionS[z] < OCCUPANCY_TIMEOUT_S;
    }

    /** Whether the door is closed now (Zigbee2MQTT's contact: true). */
    public boolean doorClosed() {
        return nowS >= doorOpenUntilS;
    }

    /** Daylight reaching zone {@code z}, in lux. */
    public double daylight(int z) {
        double sun = Math.sin(2 * Math.PI * (nowS / daySeconds + dayPhase));
        return Math.max(0, sun) * NOON_LUX * clouds * window[z];
    }

    /** The illuminance in zone {@code z}: daylight plus the lamps. */
    public double lux(int z) {
        double lux = daylight(z);
        for (int l = 0; l < zones.size(); l++) {
            double share = l == z ? 1 : Math.abs(l - z) == 1 ? SPILL : 0;
            lux += brightness[l] * LAMP_LUX * share;
        }
        return lux;
    }

    /**
     * Whether the teacher wants zone {@code z}'s lamp on: someone is there (or left less than {@link #LINGER_S} ago)
     * and daylight is too dim.
     */
    public boolean wantsLight(int z) {
        return (personZone == z || nowS - leftS[z] < LINGER_S) && daylight(z) < DARK_LUX;
    }

    public double brightness(int z) {
        return brightness[z];
    }

    /** Sets a lamp's brightness, 0..1. */
    public void lamp(int z, double level) {
        brightness[z] = Math.max(0, Math.min(1, level));
    }

    /** Energy used by each zone's lamp so far, in watt-hours, by zone. */
    public Map<String, Double> energyWh() {
        Map<String, Double> m = new LinkedHashMap<>();
        for (int z = 0; z < zones.size(); z++) {
            m.put(zones.get(z), energyWh[z]);
        }
        return m;
    }

    public double temperatureC() {
        return temperatureC;
    }

    public double humidityPct() {
        return humidityPct;
    }

    /** The zone's index, or -1. */
    public int zone(String name) {
        return zones.indexOf(name);
    }

    /** The zones whose lamp is on. */
    public List<String> lampsOn() {
        List<String> on = new ArrayList<>();
        for (int z = 0; z < zones.size(); z++) {
            if (brightness[z] > 0) {
                on.add(zones.get(z));
            }
        }
        return on;
    }
}
