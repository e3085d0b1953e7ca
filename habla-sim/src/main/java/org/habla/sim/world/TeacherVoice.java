package org.habla.sim.world;

/**
 * How the teacher reaches a particular robot: the Pioneer's teacher plays a note into the laptop microphone and
 * types {@code +1}/{@code -1} on the keyboard; the Aibo's teacher speaks and touches the robot's head or back.
 * Called on the sim clock's thread: implementations queue the sound or the line and return at once.
 */
public interface TeacherVoice {

    /**
     * Gives the command {@code label} (one of {@link TeacherSettings#LABELS}) the way this robot perceives it.
     *
     * @return how long, in sim seconds, the command takes to give (the note or the utterance): the teacher
     *         judges the robot from the end of it
     */
    double giveCommand(String label);

    /** Gives a reward in [-1, 1]: positive is pleasure, negative is pain. */
    void giveReward(double value);
}
