package org.habla.sim.world;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * One running simulation's shared state: the world, where the target is now, the robot's body and the teacher.
 * Each step it moves the body and lets the teacher act; the ground-truth server reads and resets it. A robot
 * simulator adds its own steppers (its protocol's periodic packets) to the same clock.
 */
public final class Scene implements SimClock.Stepper {

    private final World world;
    private final Body body;
    private final Teacher teacher;
    private volatile Target target;
    private volatile double nowS;
    private volatile int episode;
    private final List<Consumer<ObjectNode>> details = new CopyOnWriteArrayList<>();
    private volatile Consumer<String> touch = sensor -> {
        throw new IllegalArgumentException("this robot has no touch sensors");
    };

    public Scene(World world, Body body, Teacher teacher) {
        this.world = Objects.requireNonNull(world, "world");
        this.body = Objects.requireNonNull(body, "body");
        this.teacher = Objects.requireNonNull(teacher, "teacher");
        this.target = world.target();
    }

    @Override
    public void step(double now, double dtS) {
        nowS = now;
        body.step(dtS, world, target);
        teacher.step(now, body.pose(), target);
    }

    public World world() {
        return world;
    }

    public Body body() {
        return body;
    }

    public Teacher teacher() {
        return teacher;
    }

    /** Where the target is now. */
    public Target target() {
        return target;
    }

    /** The sim time of the last step. */
    public double nowS() {
        return nowS;
    }

    /** Starts a new episode: the robot (at rest) and optionally the target put somewhere. */
    public synchronized void reset(Pose2 robot, Target newTarget) {
        Target t = newTarget == null ? target : newTarget;
        Pose2 p = robot == null ? world.robotStart() : robot;
        if (world.clearance(p.xM(), p.yM(), t) < body.limits().radiusM()) {
            throw new IllegalArgumentException("the robot would overlap a wall or the target at (" + p.xM() + ", "
                    + p.yM() + ")");
        }
        target = t;
        body.placeAt(p);
        teacher.newEpisode();
        episode++;
    }

    /** Sets what happens when an operator touches a sensor ({@code head}, {@code back}); the Aibo has some. */
    public void onTouch(Consumer<String> handler) {
        this.touch = Objects.requireNonNull(handler, "handler");
    }

    /** Touches a sensor of the robot. */
    public void touch(String sensor) {
        touch.accept(sensor);
    }

    /** Adds robot-specific facts to every ground-truth line (the Aibo's e-stop, head and speaker). */
    public void addTruthDetail(Consumer<ObjectNode> detail) {
        details.add(Objects.requireNonNull(detail, "detail"));
    }

    /** The ground-truth line: {@link #truth()} in the contract's shape plus the robot's details. */
    public ObjectNode truthJson() {
        ObjectNode o = truth().toJson();
        details.forEach(d -> d.accept(o));
        return o;
    }

    /** Where everything is now; under the scene's lock, so a line never has a new episode with the old pose. */
    public synchronized GroundTruth truth() {
        Pose2 robot = body.pose();
        Target t = target;
        double distance = Math.max(0, t.surfaceDistance(robot.xM(), robot.yM()) - body.limits().radiusM());
        return new GroundTruth(nowS, robot, t, distance, robot.bearingTo(t.xM(), t.yM()), body.stalled(),
                teacher.present(), teacher.lastCommand(), teacher.lastReward(), teacher.episodeCommands(),
                teacher.episodePlus(), teacher.episodeMinus(), episode);
    }
}
