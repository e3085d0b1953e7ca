package org.habla.sim.scenario;

import java.util.Objects;

/**
 * How well the robot obeyed during one phase of an episode (for instance {@code teaching}): of the commands
 * the teacher judged, how many the robot carried out.
 *
 * @param phase    the phase's name as the scenario calls it
 * @param commands commands judged in the phase (≥ 0)
 * @param obeyed   of them, the ones obeyed (0 … commands)
 */
public record PhaseObedience(String phase, int commands, int obeyed) {

    public PhaseObedience {
        Objects.requireNonNull(phase, "phase");
        if (phase.isBlank()) {
            throw new IllegalArgumentException("a phase needs a name");
        }
        if (commands < 0 || obeyed < 0 || obeyed > commands) {
            throw new IllegalArgumentException("phase '" + phase + "': need 0 <= obeyed <= commands, got obeyed "
                    + obeyed + " of " + commands);
        }
    }

    /** The share of commands obeyed, 0 … 1; NaN when no command was judged. */
    public double fraction() {
        return commands == 0 ? Double.NaN : (double) obeyed / commands;
    }

    /** This phase's counts added to another's of the same phase. */
    PhaseObedience plus(PhaseObedience other) {
        return new PhaseObedience(phase, commands + other.commands, obeyed + other.obeyed);
    }
}
