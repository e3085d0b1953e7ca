package org.habla.sim.world;

import java.util.Objects;

/**
 * The scripted teacher of the paper's experiments. While present, every {@code commandEveryS} it gives the command
 * that brings the robot towards the target (|bearing| above {@code turnThresholdRad} → {@code left}/{@code right},
 * else {@code forward}), then {@code judgeAfterS} after the command got across (at once for a note, at the end
 * of a spoken phrase) judges what the robot did meanwhile: +1 if the heading
 * changed the commanded way (turns) or the robot moved forward/back as commanded, −1 otherwise. A robot that has
 * not moved at all by then is given up to {@code patienceS} more, and judged on its first visible move: a teacher
 * watches for the robot's answer, and a robot that heard the words late (a recogniser on a busy computer) is not
 * punished for a correct move the teacher did not wait for. Commands and
 * rewards go out through a {@link TeacherVoice}. An operator (the ground-truth server) may also make it say a
 * command or give a reward at once, present or not.
 *
 * <p>Pure logic with no clock of its own: the scene calls {@link #step} with sim time and where things are.
 * Thread-safe.
 */
public final class Teacher {

    private final TeacherSettings settings;
    private final TeacherVoice voice;
    private boolean present;
    private double nowS;
    private double nextCommandS;
    private String pendingLabel;
    private Pose2 pendingFrom;
    private double judgeAtS;
    private double judgeByS;
    private String lastCommand;
    private Double lastReward;
    private int episodeCommands;
    private int episodePlus;
    private int episodeMinus;
    private int commands;
    private int rewards;

    public Teacher(TeacherSettings settings, TeacherVoice voice) {
        this.settings = Objects.requireNonNull(settings, "settings");
        this.voice = Objects.requireNonNull(voice, "voice");
        this.present = settings.present();
        this.nextCommandS = settings.commandEveryS();
    }

    /** The command that brings a robot at {@code robot} towards {@code target}. */
    public String commandTowards(Pose2 robot, Target target) {
        double bearing = robot.bearingTo(target.xM(), target.yM());
        if (bearing > settings.turnThresholdRad()) {
            return "left";
        }
        if (bearing < -settings.turnThresholdRad()) {
            return "right";
        }
        return "forward";
    }

    /** Advances the teacher to sim time {@code now}: judges a due command, then gives the next one if due. */
    public synchronized void step(double now, Pose2 robot, Target target) {
        nowS = now;
        if (pendingLabel != null && now >= judgeAtS - 1e-9 && (moved(pendingFrom, robot) || now >= judgeByS - 1e-9)) {
            double reward = obeyed(pendingLabel, pendingFrom, robot) ? 1 : -1;
            pendingLabel = null;
            nextCommandS = Math.max(nextCommandS, now + 0.5);
            reward(reward);
        }
        if (present && pendingLabel == null && now >= nextCommandS - 1e-9) {
            command(commandTowards(robot, target), robot);
        }
    }

    /** Gives {@code label} now and judges it {@code judgeAfterS} later, present or not. */
    public synchronized void commandNow(String label, Pose2 robot) {
        if (!TeacherSettings.LABELS.contains(label)) {
            throw new IllegalArgumentException("unknown command label '" + label + "' (labels: " + TeacherSettings.LABELS + ")");
        }
        command(label, robot);
    }

    /** Gives a reward now. */
    public synchronized void rewardNow(double value) {
        if (!(value >= -1 && value <= 1)) {
            throw new IllegalArgumentException("a reward must be a number in [-1, 1], was " + value);
        }
        reward(value);
    }

    /** The teacher walks in (next command one period from now) or out (a pending judgement is dropped). */
    public synchronized void setPresent(boolean p) {
        if (p && !present) {
            nextCommandS = nowS + settings.commandEveryS();
        }
        if (!p) {
            pendingLabel = null;
        }
        present = p;
    }

    public synchronized boolean present() {
        return present;
    }

    /** The last command given, or null. */
    public synchronized String lastCommand() {
        return lastCommand;
    }

    /** The last reward given, or null. */
    public synchronized Double lastReward() {
        return lastReward;
    }

    /** How many commands the teacher has given. */
    public synchronized int commandCount() {
        return commands;
    }

    /** How many rewards the teacher has given. */
    public synchronized int rewardCount() {
        return rewards;
    }

    public TeacherSettings settings() {
        return settings;
    }

    /** Whether a robot that went from {@code from} to {@code to} did what {@code label} asked. */
    boolean obeyed(String label, Pose2 from, Pose2 to) {
        double turned = Pose2.normalize(to.thetaRad() - from.thetaRad());
        double advanced = from.forwardTo(to);
        return switch (label) {
            case "left" -> turned > settings.minTurnRad();
            case "right" -> turned < -settings.minTurnRad();
            case "forward" -> advanced > settings.minMoveM();
            case "back" -> advanced < -settings.minMoveM();
            default -> false;
        };
    }

    /** Whether a robot that went from {@code from} to {@code to} visibly did anything: turned or moved either way. */
    boolean moved(Pose2 from, Pose2 to) {
        return Math.abs(Pose2.normalize(to.thetaRad() - from.thetaRad())) > settings.minTurnRad()
                || Math.abs(from.forwardTo(to)) > settings.minMoveM();
    }

    private void command(String label, Pose2 robot) {
        pendingLabel = label;
        pendingFrom = robot;
        lastCommand = label;
        commands++;
        episodeCommands++;
        double soundS = voice.giveCommand(label);
        // Judged from the end of the note or the utterance: a robot cannot act on a command before it heard it.
        judgeAtS = nowS + soundS + settings.judgeAfterS();
        judgeByS = judgeAtS + settings.patienceS();
        nextCommandS = Math.max(nowS + settings.commandEveryS(), judgeAtS + 0.5);
    }

    private void reward(double value) {
        lastReward = value;
        rewards++;
        if (value > 0) {
            episodePlus++;
        } else if (value < 0) {
            episodeMinus++;
        }
        voice.giveReward(value);
    }

    /** A new episode: the counts start again and a command not yet judged is forgotten. */
    public synchronized void newEpisode() {
        pendingLabel = null;
        episodeCommands = 0;
        episodePlus = 0;
        episodeMinus = 0;
    }

    /** What the teacher gave since the episode began: commands, rewards of pleasure (> 0) and of pain (< 0). */
    public record Tally(int commands, int plus, int minus) {
    }

    /** The episode's counts at once. */
    public synchronized Tally episodeTally() {
        return new Tally(episodeCommands, episodePlus, episodeMinus);
    }

    /** Commands given since the episode began. */
    public synchronized int episodeCommands() {
        return episodeCommands;
    }

    /** Rewards of pleasure given since the episode began. */
    public synchronized int episodePlus() {
        return episodePlus;
    }

    /** Rewards of pain given since the episode began. */
    public synchronized int episodeMinus() {
        return episodeMinus;
    }
}
