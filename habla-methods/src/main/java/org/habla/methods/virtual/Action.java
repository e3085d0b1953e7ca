package org.habla.methods.virtual;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * The action method, type {@code action}: the high-level action a control architecture writes. Input
 * {@code action} takes one of the labels {@code forward}, {@code left}, {@code right}, {@code back} and
 * {@code stop}; each becomes a motion {@code [vMps, wRadps]} on output {@code motion} (turn rate positive
 * counter-clockwise) that is held for {@code durationMs} and then returns to zero. {@code stop} zeros the
 * motion at once; a new label replaces the one being held and starts its time again. Output {@code action}
 * echoes every accepted label, so every client of the socket sees what the robot was told. When the engine
 * stops the robot (the motion watchdog), the label being held is dropped and {@code motion} says zero at once:
 * the socket never shows a motion the robot is not making.
 *
 * <p>A control client that writes anything else gets an error line naming the labels: the value is refused
 * before it is queued. A label from a wired method that is not known is counted and ignored.
 */
public final class Action extends VirtualMethod {

    /** The labels an action may be, in the order the error message lists them. */
    public static final List<String> LABELS = List.of("forward", "left", "right", "back", "stop");

    private static final Duration TICK = Duration.ofMillis(20);

    private static final InputPort<TextValue> ACTION = InputPort.of("action", TextValue.class, Delivery.queue(16));
    private static final OutputPort<VectorValue> MOTION = OutputPort.of("motion", VectorValue.class,
            new Shape(org.habla.sample.PayloadKind.VECTOR, "m/s, rad/s", List.of("vMps", "wRadps"),
                    "the motion of the action being held; zero when none is"));
    private static final OutputPort<TextValue> ECHO = OutputPort.of("action", TextValue.class,
            Shape.text("every accepted action label, as written"));
    static final Ports PORTS = Ports.of(ACTION, MOTION, ECHO);

    private final ActionParams params;
    private final Output<VectorValue> motion = output(MOTION);
    private final Output<TextValue> echo = output(ECHO);

    private long holdUntilMicros;
    private boolean holding;
    private long refused;

    Action(ActionParams params) {
        this.params = params;
        input(ACTION, this::onAction, Action::refusal);
        tickEvery(TICK);
    }

    /** Why a written value is not an action, or null when it is one. */
    static String refusal(TextValue value) {
        return LABELS.contains(normalise(value.text())) ? null
                : "unknown action '" + abbreviate(value.text()) + "'; actions are " + String.join(", ", LABELS);
    }

    private void onAction(TextValue value, Sample sample) {
        String label = normalise(value.text());
        double[] vw = switch (label) {
            case "forward" -> new double[] {params.forwardMps(), 0};
            case "back" -> new double[] {-params.backMps(), 0};
            case "left" -> new double[] {0, params.turnRadps()};
            case "right" -> new double[] {0, -params.turnRadps()};
            case "stop" -> new double[] {0, 0};
            default -> null;
        };
        if (vw == null) {
            if (refused++ == 0) {
                log().warn("{}: {} (further unknown labels are only counted)", id(), refusal(value));
            }
            return;
        }
        emit(echo, new TextValue(label));
        emit(motion, VectorValue.wrap(vw));
        holding = !label.equals("stop");
        holdUntilMicros = nowMicros() + params.durationMs() * 1000L;
    }

    @Override
    protected void onTick(long nowMicros) {
        if (holding && nowMicros >= holdUntilMicros) {
            holding = false;
            emit(motion, VectorValue.of(0, 0));
        }
    }

    @Override
    protected void onMotionStopped() {
        if (holding) {
            holding = false;
            emit(motion, VectorValue.of(0, 0));
        }
    }

    /** Labels from wired methods that were not actions, since start. */
    public long refused() {
        return refused;
    }

    private static String normalise(String text) {
        return text.strip().toLowerCase(Locale.ROOT);
    }

    private static String abbreviate(String text) {
        String t = text.strip();
        return t.length() <= 40 ? t : t.substring(0, 40) + "…";
    }

    /** Makes {@code action} methods. */
    public static final class Provider extends SimpleMethodProvider<ActionParams> {
        public Provider() {
            super("action", "Turns an action label (forward, left, right, back, stop) into a motion held for a while",
                    ActionParams.class, PORTS, (layer, p) -> new Action(p), Layer.VIRTUAL);
        }
    }
}
