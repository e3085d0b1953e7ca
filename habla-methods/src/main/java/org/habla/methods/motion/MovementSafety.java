package org.habla.methods.motion;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.perception.NearestObstacle;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * The movement-safety method, type {@code movement-safety}: keeps a mobile base from driving into what
 * its range sensors see. Input {@code motion} {@code [vMps, wRadps]} goes out on output {@code motion}
 * within the top speeds (params, else the optional {@code limits} input), except that forward motion is
 * vetoed — its speed set to zero, turning still allowed — while the nearest obstacle ahead is closer than
 * {@code stopDistanceM}, and backward motion likewise for an obstacle behind. Ahead and behind come from
 * the {@code nearest} record's {@code aheadM} and {@code behindM} (from {@code nearest-distance}), or, when
 * it lacks them, from its {@code distanceM} and {@code angleRad} and the cones of {@code coneRad}. A motion
 * being held is checked again on every nearest record, so an obstacle that comes close stops it. With no
 * nearest record for {@code maxAgeMs}, translation is vetoed too. Output {@code veto} says why, once
 * each time a veto begins; and the control clients whose values reach this method are told as a {@code veto}
 * notice — the reason, the limit and what was measured — for every motion they ask for that is vetoed, and
 * when a veto begins on a motion being held.
 */
public final class MovementSafety extends ProcessingMethod {

    private static final InputPort<VectorValue> MOTION = InputPort.of("motion", VectorValue.class, Delivery.latest());
    private static final InputPort<RecordValue> NEAREST = InputPort.of("nearest", RecordValue.class, Delivery.latest());
    private static final InputPort<RecordValue> LIMITS = InputPort.optional("limits", RecordValue.class,
            Delivery.latest());
    /** The safe motion (the input of the same name is the one asked for). */
    private static final OutputPort<VectorValue> OUT = OutputPort.of("motion", VectorValue.class,
            new Shape(PayloadKind.VECTOR, "m/s, rad/s", List.of("vMps", "wRadps"), "the motion that is safe to make"));
    private static final OutputPort<TextValue> VETO = OutputPort.of("veto", TextValue.class,
            Shape.text("why a motion was stopped, once each time a veto begins"));
    static final Ports PORTS = Ports.of(MOTION, NEAREST, LIMITS, OUT, VETO);

    private final MovementSafetyParams params;
    private final Output<VectorValue> out = output(OUT);
    private final Output<TextValue> vetoOut = output(VETO);

    private MotionLimits limits;
    private double wantedV;
    private double wantedW;
    private boolean wanted;
    private double aheadM = Double.POSITIVE_INFINITY;
    private double behindM = Double.POSITIVE_INFINITY;
    private long nearestMicros = Long.MIN_VALUE;
    private double[] lastSent;
    private String veto = "";
    private long vetoes;
    private long malformed;

    MovementSafety(MovementSafetyParams params) {
        this.params = params;
        this.limits = MotionLimits.NONE.overriddenBy(params.maxVelMps(), params.maxRotVelRadps());
        input(MOTION, this::onMotion);
        input(NEAREST, this::onNearest);
        input(LIMITS, this::onLimits);
        tickEvery(Duration.ofMillis(100));
    }

    private void onLimits(RecordValue value, Sample sample) {
        limits = MotionLimits.fromRecord(value)
                .overriddenBy(params.maxVelMps(), params.maxRotVelRadps());
        if (wanted) {
            decide(false);
        }
    }

    private void onMotion(VectorValue value, Sample sample) {
        Optional<double[]> m = MotionLimits.motionOf(value);
        if (m.isEmpty()) {
            if (malformed++ == 0) {
                log().warn("{}: a motion that is not [vMps, wRadps] of finite numbers is taken as zero: {}", id(), value);
            }
        }
        wantedV = m.map(a -> a[0]).orElse(0.0);
        wantedW = m.map(a -> a[1]).orElse(0.0);
        wanted = true;
        decide(true);
    }

    private void onNearest(RecordValue value, Sample sample) {
        NearestObstacle nearest = NearestObstacle.fromRecord(value);
        double ahead = nearest.aheadM();
        double behind = nearest.behindM();
        if (Double.isNaN(ahead) || Double.isNaN(behind) || ahead < 0 || behind < 0) {
            double d = nearest.distanceM();
            double a = nearest.angleRad();
            if (Double.isNaN(d) || Double.isNaN(a) || d < 0) {
                if (malformed++ == 0) {
                    log().warn("{}: a nearest record without finite aheadM/behindM or distanceM/angleRad was ignored",
                            id());
                }
                return;
            }
            boolean real = nearest.valid();
            ahead = real && Math.abs(a) <= params.coneRad() ? d : Double.POSITIVE_INFINITY;
            behind = real && Math.PI - Math.abs(a) <= params.coneRad() ? d : Double.POSITIVE_INFINITY;
        }
        aheadM = ahead;
        behindM = behind;
        nearestMicros = nowMicros();
        if (wanted) {
            decide(false);
        }
    }

    @Override
    protected void onTick(long nowMicros) {
        if (wanted && !fresh(nowMicros)) {
            decide(false);
        }
    }

    private boolean fresh(long now) {
        return nearestMicros != Long.MIN_VALUE && now - nearestMicros <= params.maxAgeMs() * 1000L;
    }

    /** Works out the safe motion; emits it when asked for anew or when it changed. */
    private void decide(boolean asked) {
        double[] vw = limits.clamp(wantedV, wantedW);
        Veto v = vetoOf(vw);
        if (v != null) {
            vw[0] = 0;
            if (veto.isEmpty()) {
                vetoes++;
                emit(vetoOut, new TextValue(v.message()));
            }
            if (asked || veto.isEmpty()) {
                tellControl("veto", v.message(), RecordValue.of(v.detail()));
            }
        }
        veto = v == null ? "" : v.message();
        if (asked || lastSent == null || lastSent[0] != vw[0] || lastSent[1] != vw[1]) {
            lastSent = vw;
            emit(out, VectorValue.wrap(vw.clone()));
        }
    }

    /** Why the translation of {@code vw} may not be made now, or null when it may. */
    private Veto vetoOf(double[] vw) {
        double v = vw[0];
        if (v == 0) {
            return null;
        }
        String direction = v > 0 ? "forward" : "backward";
        long now = nowMicros();
        if (!fresh(now)) {
            Long ageMs = nearestMicros == Long.MIN_VALUE ? null : (now - nearestMicros) / 1_000;
            return new Veto(String.format(Locale.ROOT, "%s motion vetoed: no fresh range data (none in the last %d ms)",
                    direction, params.maxAgeMs()), new VetoDetail.NoRangeData(v, vw[1], params.maxAgeMs(), ageMs));
        }
        double obstacle = v > 0 ? aheadM : behindM;
        if (obstacle >= params.stopDistanceM()) {
            return null;
        }
        return new Veto(String.format(Locale.ROOT, "%s motion vetoed: obstacle %.2f m %s (stop distance %.2f m)",
                direction, obstacle, v > 0 ? "ahead" : "behind", params.stopDistanceM()),
                new VetoDetail.Obstacle(v, vw[1], obstacle, params.stopDistanceM()));
    }

    /** A veto: the sentence for people and the fields for programs. */
    private record Veto(String message, VetoDetail detail) {
    }

    /** The engine stopped the robot: nothing is wanted any more, and the next motion is decided afresh. */
    @Override
    protected void onMotionStopped() {
        wanted = false;
        wantedV = 0;
        wantedW = 0;
        lastSent = null;
        veto = "";
    }

    /** Vetoes begun since start. */
    public long vetoes() {
        return vetoes;
    }

    /** Makes {@code movement-safety} methods. */
    public static final class Provider extends SimpleMethodProvider<MovementSafetyParams> {
        public Provider() {
            super("movement-safety", "Vetoes motion towards an obstacle nearer than a stop distance, within top speeds",
                    MovementSafetyParams.class, PORTS, (layer, p) -> new MovementSafety(p), Layer.PROCESSING);
        }
    }
}
