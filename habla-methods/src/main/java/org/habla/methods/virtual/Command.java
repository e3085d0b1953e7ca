package org.habla.methods.virtual;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
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

/**
 * The command method, type {@code command}: the teacher's command as a label. Input {@code in} takes what
 * was heard — a note name from {@code note-recognition} ({@code C5}) or a phrase from
 * {@code speech-recognition} ({@code go forward}) — and output {@code command} emits the label the
 * {@code map} param gives it ({@code forward}), once per command. Matching ignores case and extra
 * spaces. Input nobody mapped is ignored and counted. With {@code debounceMs}, a label repeated within
 * that time (one long note heard twice) is emitted only once.
 */
public final class Command extends VirtualMethod {

    private static final InputPort<TextValue> IN = InputPort.of("in", TextValue.class, Delivery.queue(32));
    private static final OutputPort<TextValue> COMMAND = OutputPort.of("command", TextValue.class,
            Shape.text("the teacher's command label, once per command"));
    static final Ports PORTS = Ports.of(IN, COMMAND);

    private final CommandParams params;
    private final Map<String, String> labels = new HashMap<>();
    private final Output<TextValue> command = output(COMMAND);

    private String lastLabel;
    private long lastMicros;
    private long ignored;
    private long debounced;

    Command(CommandParams params) {
        this.params = params;
        params.map().forEach((heard, label) -> labels.put(key(heard), label.strip()));
        input(IN, this::onHeard);
    }

    /** The form in which heard input is matched: trimmed, lower case, single spaces. */
    static String key(String text) {
        return text == null ? "" : text.strip().replaceAll("\\s+", " ").toLowerCase(Locale.ROOT);
    }

    private void onHeard(TextValue heard, Sample sample) {
        String label = labels.get(key(heard.text()));
        if (label == null) {
            if (ignored++ == 0) {
                log().info("{}: '{}' means no command; such input is ignored and counted", id(),
                        heard.text().length() > 40 ? heard.text().substring(0, 40) + "…" : heard.text());
            }
            return;
        }
        long now = nowMicros();
        if (label.equals(lastLabel) && now - lastMicros < params.debounceMs() * 1000L) {
            debounced++;
            return;
        }
        lastLabel = label;
        lastMicros = now;
        emit(command, new TextValue(label));
    }

    /** Inputs that no map entry matched, since start. */
    public long ignored() {
        return ignored;
    }

    /** Repeats dropped by the debounce, since start. */
    public long debounced() {
        return debounced;
    }

    /** Makes {@code command} methods. */
    public static final class Provider extends SimpleMethodProvider<CommandParams> {
        public Provider() {
            super("command", "Maps a heard note or phrase to the teacher's command label",
                    CommandParams.class, PORTS, (layer, p) -> new Command(p), Layer.VIRTUAL);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
