package org.habla.sim.pioneer;

import java.io.IOException;
import java.util.Random;
import org.habla.sim.world.Body;
import org.habla.sim.world.LineServer;
import org.habla.sim.world.Scene;
import org.habla.sim.world.SimClock;
import org.habla.sim.world.Teacher;
import org.habla.sim.world.TruthServer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A complete simulated Pioneer 2 DX in its world, behind four loopback sockets: the robot's ARCOS port, the
 * laptop microphone's PCM stream, the teacher's keyboard, and the ground-truth server. Everything runs on one
 * {@link SimClock} with 10 ms steps, at the options' speed.
 *
 * <pre>
 * try (PioneerSim sim = PioneerSim.start(PioneerSimOptions.defaults())) { ... }
 * </pre>
 */
public final class PioneerSim implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PioneerSim.class);
    /** The fixed physics step, sim seconds. */
    public static final double STEP_S = 0.01;

    private final SimClock clock;
    private final Scene scene;
    private final PioneerController controller;
    private final ArcosServer arcos;
    private final PcmServer mic;
    private final LineServer keys;
    private final TruthServer truth;

    private PioneerSim(PioneerSimOptions o) throws IOException {
        Random random = new Random(o.seed());
        clock = new SimClock(o.speed(), STEP_S);
        PcmServer micServer = null;
        LineServer keyServer = null;
        ArcosServer arcosServer = null;
        TruthServer truthServer = null;
        try {
            micServer = new PcmServer(o.micPort());
            keyServer = new LineServer("keyboard", o.keysPort(), null);
            Microphone microphone = new Microphone(micServer, new Random(random.nextLong()));
            Teacher teacher = new Teacher(o.world().teacher().withPresent(o.teacherOn()),
                    new PioneerTeacherVoice(o.world().teacher(), microphone, keyServer));
            scene = new Scene(o.world(), new Body(P2dx.bodyLimits(), o.world().robotStart()), teacher);
            controller = new PioneerController(scene, new Random(random.nextLong()), o.sonarNoiseM());
            arcosServer = new ArcosServer(controller, o.arcosPort());
            truthServer = new TruthServer(scene, o.truthPort());
            clock.add(controller);
            clock.add(scene);
            clock.add(microphone);
            clock.add(truthServer);
        } catch (IOException | RuntimeException e) {
            for (AutoCloseable c : new AutoCloseable[] {micServer, keyServer, arcosServer, truthServer}) {
                closeQuietly(c);
            }
            throw e;
        }
        mic = micServer;
        keys = keyServer;
        arcos = arcosServer;
        truth = truthServer;
    }

    /** Builds the simulation, opens its sockets and starts sim time. */
    public static PioneerSim start(PioneerSimOptions options) throws IOException {
        PioneerSim sim = new PioneerSim(options);
        sim.clock.start();
        LOG.info("simulated Pioneer in '{}' at {}x: ARCOS {}, microphone {}, keyboard {}, ground truth {}",
                options.world().name(), options.speed(), sim.arcosPort(), sim.micPort(), sim.keysPort(),
                sim.truthPort());
        return sim;
    }

    public int arcosPort() {
        return arcos.port();
    }

    public int micPort() {
        return mic.port();
    }

    public int keysPort() {
        return keys.port();
    }

    public int truthPort() {
        return truth.port();
    }

    public SimClock clock() {
        return clock;
    }

    public Scene scene() {
        return scene;
    }

    @Override
    public void close() {
        clock.close();
        for (AutoCloseable c : new AutoCloseable[] {arcos, mic, keys, truth}) {
            closeQuietly(c);
        }
        LOG.info("simulated Pioneer stopped at t={} s: {}", String.format("%.1f", clock.nowS()), controller.counters());
    }

    private static void closeQuietly(AutoCloseable c) {
        if (c == null) {
            return;
        }
        try {
            c.close();
        } catch (Exception e) {
            LOG.debug("closing {}: {}", c, e.toString());
        }
    }
}
