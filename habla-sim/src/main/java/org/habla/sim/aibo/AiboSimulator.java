package org.habla.sim.aibo;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.habla.sim.world.Body;
import org.habla.sim.world.Scene;
import org.habla.sim.world.Segment;
import org.habla.sim.world.SimClock;
import org.habla.sim.world.Target;
import org.habla.sim.world.Teacher;
import org.habla.sim.world.TeacherVoice;
import org.habla.sim.world.TruthServer;
import org.habla.sim.world.World;

/**
 * A simulated Sony Aibo ERS-7 in a world: Tekkotsu's servers on loopback over a body that walks on the
 * floor, infrared sensors and a camera that see the walls and the pink ball, a microphone that hears the
 * teacher's spoken commands and touch sensors the teacher presses to reward it, plus the ground-truth
 * server. Everything runs on one simulated clock with OPEN-R's 8 ms motion frame as its step:
 * <pre>
 * each step:  walk remote control → body velocities   (nothing while the e-stop is on or after 3 s of silence)
 *             body moves, collides; the teacher acts  (the world's Scene)
 *             infrared rays cast from the new pose
 *             ground truth every 100 ms
 * </pre>
 * The world state, camera and microphone servers send at their own periods of the same clock.
 */
public final class AiboSimulator implements AutoCloseable {

    /** OPEN-R's motion frame, the simulation's step. */
    public static final double STEP_S = 0.008;
    /** How long the teacher (or a {@code touch} operation) presses a touch sensor. */
    public static final long TOUCH_MS = 500;
    /** The body reaches its walking speed in about 0.3 s. */
    static final Body.Limits LIMITS = new Body.Limits(Ers7Geometry.BODY_RADIUS_M, Ers7Body.MAX_FORWARD_MPS,
            Ers7Body.MAX_ROTATE_RADPS, 0.6, 6.0);

    /**
     * How to run it.
     *
     * @param truthPort the ground-truth server's port (0: any free port)
     * @param teacher   whether the teacher is present at the start
     */
    public record Options(World world, double speed, long seed, TekkotsuPorts ports, int truthPort,
            boolean teacher) {

        /** Tekkotsu's default ports, ground truth on 10199, real time, seed 1, the teacher present. */
        public static Options defaults(World world) {
            return new Options(world, 1, 1, TekkotsuPorts.withBase(TekkotsuPorts.DEFAULT_BASE), 10_199, true);
        }

        /** Every server and the ground truth on free ports (tests). */
        public Options onFreePorts() {
            return new Options(world, speed, seed, TekkotsuPorts.ANY_FREE, 0, teacher);
        }

        public Options withSpeed(double s) {
            return new Options(world, s, seed, ports, truthPort, teacher);
        }

        public Options withSeed(long n) {
            return new Options(world, speed, n, ports, truthPort, teacher);
        }

        public Options withPorts(TekkotsuPorts p, int truth) {
            return new Options(world, speed, seed, p, truth, teacher);
        }

        public Options withTeacher(boolean present) {
            return new Options(world, speed, seed, ports, truthPort, present);
        }
    }

    private final SimClock clock;
    private final AiboTime time;
    private final Scene scene;
    private final Ers7Body ers7 = new Ers7Body();
    private final Microphone microphone;
    private final SpeakerLog said = new SpeakerLog();
    private final Infrared infrared;
    private final Utterances utterances;
    private final List<double[]> walls = new ArrayList<>();
    private final TekkotsuServers servers;
    private final TruthServer truth;
    private volatile double[] lastIr = new double[3];
    private volatile String lastPhrase;

    public AiboSimulator(Options o) throws IOException {
        this.clock = new SimClock(o.speed(), STEP_S);
        this.time = new AiboTime(clock);
        this.microphone = new Microphone(o.seed());
        this.infrared = new Infrared(o.seed() + 1);
        this.utterances = Utterances.shipped(o.seed() + 2);
        for (Segment s : o.world().walls()) {
            walls.add(new double[] {s.x1(), s.y1(), s.x2(), s.y2()});
        }
        Body body = new Body(LIMITS, o.world().robotStart());
        Teacher teacher = new Teacher(o.world().teacher().withPresent(o.teacher()), new Voice());
        for (String phrase : o.world().teacher().phrases().values()) {
            if (!utterances.has(phrase)) {
                throw new IllegalArgumentException("the world's teacher says '" + phrase
                        + "', but no recorded take says it");
            }
        }
        this.scene = new Scene(o.world(), body, teacher);
        scene.onTouch(this::touch);
        scene.addTruthDetail(this::details);
        ers7.onEStopChange(stopped -> {
            if (stopped) {
                body.halt();
            }
        });
        clock.add(this::move);
        clock.add(scene);
        clock.add(this::sense);
        TekkotsuServers s = null;
        TruthServer t = null;
        try {
            s = new TekkotsuServers(o.ports(), time, ers7, microphone, said, at -> view());
            t = new TruthServer(scene, o.truthPort());
        } catch (IOException | RuntimeException e) {
            if (s != null) {
                s.close();
            }
            throw e;
        }
        this.servers = s;
        this.truth = t;
        clock.add(truth);
    }

    /** Starts the clock: the robot boots (e-stop on, only the controller and e-stop servers running). */
    public void start() {
        clock.start();
    }

    public TekkotsuPorts ports() {
        return servers.ports();
    }

    public int truthPort() {
        return truth.port();
    }

    public Scene scene() {
        return scene;
    }

    public Ers7Body ers7() {
        return ers7;
    }

    public SimClock clock() {
        return clock;
    }

    public SpeakerLog said() {
        return said;
    }

    /** The infrared distances last read, [near, far, chest] in metres. */
    public double[] infrared() {
        return lastIr.clone();
    }

    private void move(double nowS, double dtS) {
        long nowMs = Math.round(nowS * 1000);
        Ers7Body.Walk w = ers7.walk(nowMs);
        scene.body().command(w.forwardMps(), w.strafeMps(), w.rotateRadps());
        ers7.step(dtS, nowMs);
    }

    private void sense(double nowS, double dtS) {
        double[] ir = infrared.read(scene.world(), scene.target(), scene.body().pose(), ers7.head());
        ers7.setInfrared(ir[0], ir[1], ir[2]);
        lastIr = ir;
    }

    /** What the camera sees now. */
    CameraView view() {
        Target ball = scene.target();
        Ers7Geometry.Ray nose = Ers7Geometry.nose(scene.body().pose(), ers7.head());
        return new CameraView(walls, Ers7Geometry.WALL_HEIGHT_M,
                new CameraView.Ball(ball.xM(), ball.yM(), ball.radiusM(), BallColours.rgb(ball.color())),
                new CameraView.CameraPose(nose.xM(), nose.yM(), nose.zM(), nose.yawRad(), nose.pitchRad()));
    }

    private void touch(String sensor) {
        int button = switch (sensor) {
            case "head" -> Ers7Layout.HEAD_BUTTON;
            case "back" -> Ers7Layout.BACK_MIDDLE_BUTTON;
            default -> throw new IllegalArgumentException("the Aibo's touch sensors are 'head' and 'back', not '"
                    + sensor + "'");
        };
        ers7.press(button, time.nowMs() + TOUCH_MS);
    }

    private void details(ObjectNode o) {
        ObjectNode aibo = o.putObject("aibo");
        aibo.put("eStop", ers7.eStopped());
        Ers7Body.HeadPose h = ers7.head();
        aibo.putObject("head").put("tiltRad", h.tiltRad()).put("panRad", h.panRad()).put("nodRad", h.nodRad());
        Ers7Body.Walk w = ers7.walk(time.nowMs());
        aibo.putObject("walk").put("forwardMps", w.forwardMps()).put("strafeMps", w.strafeMps())
                .put("rotateRadps", w.rotateRadps());
        double[] ir = lastIr;
        aibo.putArray("irM").add(ir[0]).add(ir[1]).add(ir[2]);
        SpeakerLog.Summary s = said.summary();
        aibo.putObject("speaker").put("packets", s.packets()).put("seconds", s.seconds())
                .put("lastAtS", s.lastAtS()).put("lastPeak", s.lastPeak()).put("rejected", s.rejected());
        if (lastPhrase == null) {
            aibo.putNull("lastPhrase");
        } else {
            aibo.put("lastPhrase", lastPhrase);
        }
    }

    /** The Aibo's teacher: commands spoken into the microphone, rewards by touch (back = pleasure, head = pain). */
    private final class Voice implements TeacherVoice {

        private double lastSeconds;

        @Override
        public double giveCommand(String label) {
            String phrase = scene.world().teacher().phrases().get(label);
            short[] take = utterances.take(phrase);
            long now = MicrophoneServer.samplesAt(time.nowMs());
            long start = microphone.play(take, now);
            lastSeconds = (double) (start + take.length - now) / Microphone.RATE_HZ;
            lastPhrase = phrase;
            return lastSeconds;
        }

        @Override
        public void giveReward(double value) {
            if (value > 0) {
                touch("back");
            } else if (value < 0) {
                touch("head");
            }
        }
    }

    @Override
    public void close() {
        truth.close();
        servers.close();
        clock.close();
    }
}
