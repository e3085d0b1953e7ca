package org.habla.methods.virtual;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.HashMap;
import java.util.Map;
import java.util.regex.Pattern;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The reward method, type {@code reward}: the teacher's pleasure or pain as one number in [-1, 1]
 * (positive: pleasure), emitted once per reward on output {@code reward}. It reads either or both of:
 * <ul>
 *   <li>input {@code text}: lines such as {@code +1}, {@code -0.5} (numbers, clamped to [-1, 1]) or words the
 *       {@code words} param maps ({@code pain}, {@code good dog}); other text is ignored and counted;</li>
 *   <li>input {@code buttons}: a record of touch sensors; a field the {@code touch} param names gives its reward
 *       when it goes from released to pressed ({@code threshold}), once per press, not while held.</li>
 * </ul>
 */
public final class Reward extends VirtualMethod {

    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)");
    private static final InputPort<TextValue> TEXT = InputPort.optional("text", TextValue.class, Delivery.queue(32));
    private static final InputPort<RecordValue> BUTTONS = InputPort.optional("buttons", RecordValue.class,
            Delivery.queue(32));
    private static final OutputPort<NumberValue> REWARD = OutputPort.of("reward", NumberValue.class,
            Shape.number("", "the teacher's reward in [-1, 1]: + pleasure, - pain; once per reward"));
    static final Ports PORTS = Ports.of(TEXT, BUTTONS, REWARD);

    private final RewardParams params;
    private final Map<String, Double> words = new HashMap<>();
    private final Map<String, Boolean> pressed = new HashMap<>();
    private final Output<NumberValue> reward = output(REWARD);

    private long ignored;

    Reward(RewardParams params) {
        this.params = params;
        params.words().forEach((w, v) -> words.put(Command.key(w), v));
        input(TEXT, this::onText);
        input(BUTTONS, this::onButtons);
    }

    private void onText(TextValue value, Sample sample) {
        String key = Command.key(value.text());
        Double r = words.get(key);
        if (r == null && key.length() <= 32 && NUMBER.matcher(key).matches()) {
            r = Math.max(-1, Math.min(1, Double.parseDouble(key)));
        }
        if (r == null) {
            if (ignored++ == 0) {
                log().info("{}: text that is no reward is ignored and counted", id());
            }
            return;
        }
        emit(reward, new NumberValue(r));
    }

    private void onButtons(RecordValue value, Sample sample) {
        for (Map.Entry<String, Double> e : params.touch().entrySet()) {
            JsonNode field = value.get(e.getKey());
            boolean down;
            if (field.isBoolean()) {
                down = field.booleanValue();
            } else if (field.isNumber() && Double.isFinite(field.doubleValue())) {
                down = field.doubleValue() >= params.threshold();
            } else {
                continue;
            }
            Boolean before = pressed.put(e.getKey(), down);
            if (down && !Boolean.TRUE.equals(before)) {
                emit(reward, new NumberValue(e.getValue()));
            }
        }
    }

    /** Text inputs that were no reward, since start. */
    public long ignored() {
        return ignored;
    }

    /** Makes {@code reward} methods. */
    public static final class Provider extends SimpleMethodProvider<RewardParams> {
        public Provider() {
            super("reward", "The teacher's pleasure or pain as a number in [-1, 1], from text lines or touch sensors",
                    RewardParams.class, PORTS, (layer, p) -> new Reward(p), Layer.VIRTUAL);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
