package org.habla.sim.world;

/**
 * How the teacher reaches a particular robot: the Pioneer's teacher plays a note into the laptop microphone and
 * types {@code +1}/{@code -1} on the keyboard; the Aibo's teacher speaks and touches the robot's head or back.
 * Called on the sim clock's thread: implementations queue the sound or the line and return at once.
 */
public interface TeacherVoice {

    /** Gives the command {@code label} (one of {@link TeacherSettings#LABELS}) the way this robot perceives it. */
    void giveCommand(String label);

    /**
     * How many sim seconds the command just given takes to get across (a spoken phrase's length, counted from
     * now); the teacher starts its {@code judgeAfterS} only after that. Zero for a command that is there at once.
     */
    default double lastCommandSeconds() {
        return 0;
    }

    /** Gives a reward in [-1, 1]: positive is pleasure, negative is pain. */
    void giveReward(double value);
}
