package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * What the room's control program did in one phase of an episode, measured on the simulator's ground truth:
 *
 * @param episode  the episode, from 1
 * @param phase    "taught, first third" … "taught, last third", or "alone"
 * @param seconds  simulated seconds the phase lasted
 * @param switches lamp switches (a lamp going on or off)
 * @param right    switches that were right: a lamp on where the person is and daylight leaves dark, or off elsewhere
 * @param wantedS  simulated seconds the person's zone wanted light
 * @param servedS  of those, the seconds its lamp was on
 * @param energyWh energy the lamps used
 * @param oracleWh energy a room that lit exactly the zone wanting light would have used
 * @param allOnWh  energy every lamp on all the time would have used
 */
record RoomPhase(int episode, String phase, double seconds, int switches, int right, double wantedS, double servedS,
        double energyWh, double oracleWh, double allOnWh) {

    double rightFraction() {
        return switches == 0 ? Double.NaN : (double) right / switches;
    }

    double servedFraction() {
        return wantedS == 0 ? Double.NaN : servedS / wantedS;
    }

    /** Energy used beyond the oracle's, as a share of what leaving every lamp on would have used beyond it. */
    double wasteFraction() {
        double room = allOnWh - oracleWh;
        return room <= 0 ? Double.NaN : Math.max(0, energyWh - oracleWh) / room;
    }

    ObjectNode toJson() {
        ObjectNode n = JsonNodeFactory.instance.objectNode().put("episode", episode).put("phase", phase)
                .put("seconds", seconds).put("switches", switches).put("right", right).put("wantedS", wantedS)
                .put("servedS", servedS).put("energyWh", energyWh).put("oracleWh", oracleWh).put("allOnWh", allOnWh);
        put(n, "rightFraction", rightFraction());
        put(n, "servedFraction", servedFraction());
        put(n, "wasteFraction", wasteFraction());
        return n;
    }

    private static void put(ObjectNode n, String field, double v) {
        if (Double.isFinite(v)) {
            n.put(field, v);
        } else {
            n.putNull(field);
        }
    }
}
