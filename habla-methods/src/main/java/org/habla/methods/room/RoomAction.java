package org.habla.methods.room;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.plugin.Param;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The room action method, type {@code room-action}: the actions a control architecture writes to a room, as
 * short texts on input {@code action} (case and extra spaces do not matter):
 *
 * <pre>
 *   desk on | desk off | desk 0.4       a lamp the lamps param names: on, off or a level 0..1
 *   all on | all off                    every lamp
 *   window open | window close | window 0.5   blinds the blinds param names: 1 open, 0 closed
 *   say good morning                    the room speaker (speaker: true)
 * </pre>
 *
 * Each lamp and each blind has an output of its own name with its level (wire it down to a {@code lamp} or a
 * {@code blinds} method); {@code say} carries the text; {@code action} echoes every accepted action; {@code lamps}
 * is a record of every lamp's level after each action. A control client that writes anything else gets an error
 * line that lists the targets; an action from a wired method that is not understood is counted and ignored.
 */
public final class RoomAction extends VirtualMethod {

    private static final Pattern NAME = Pattern.compile("[a-z][a-z0-9_-]{0,31}");
    private static final Set<String> RESERVED = Set.of("all", "say", "action", "lamps");

    private final Params params;
    private final Map<String, Output<NumberValue>> lampOutputs = new LinkedHashMap<>();
    private final Map<String, Output<NumberValue>> blindOutputs = new LinkedHashMap<>();
    private final Map<String, Double> levels = new LinkedHashMap<>();
    private static final InputPort<TextValue> ACTION = InputPort.of("action", TextValue.class, Delivery.queue(32));
    private static final OutputPort<TextValue> ECHO = OutputPort.of("action", TextValue.class,
            Shape.text("every accepted action"));
    private static final OutputPort<RecordValue> LAMPS = OutputPort.of("lamps", RecordValue.class,
            Shape.record("every lamp's level 0..1 after the last action", LampLevels.LAYOUT));
    private static final OutputPort<TextValue> SAY = OutputPort.of("say", TextValue.class,
            Shape.text("what the room says"));

    private final Output<TextValue> say;
    private final Output<TextValue> echo = output(ECHO);
    private final Output<RecordValue> lamps = output(LAMPS);
    private long refused;

    /** The params of a {@code room-action} method. */
    public record Params(
            @Param(value = "the lamps, each an output of its name with a level 0..1", defaultValue = "[]")
            List<String> lamps,
            @Param(value = "the blinds, each an output of its name with how far they are open, 0..1",
                    defaultValue = "[]") List<String> blinds,
            @Param(value = "whether the room has a speaker ('say ...' on output say)", defaultValue = "false")
            boolean speaker) {

        public Params {
            lamps = List.copyOf(lamps);
            blinds = List.copyOf(blinds);
            if (lamps.isEmpty() && blinds.isEmpty() && !speaker) {
                throw new IllegalArgumentException("lamps, blinds, speaker: the room needs something to act on");
            }
            Set<String> seen = new HashSet<>();
            for (String n : concat(lamps, blinds)) {
                if (!NAME.matcher(n).matches() || RESERVED.contains(n)) {
                    throw new IllegalArgumentException("'" + n + "' cannot name a lamp or blinds: use lower-case "
                            + "letters, digits, '_' or '-', and none of " + RESERVED);
                }
                if (!seen.add(n)) {
                    throw new IllegalArgumentException("'" + n + "' is named twice among the lamps and blinds");
                }
            }
        }

        private static List<String> concat(List<String> a, List<String> b) {
            List<String> all = new ArrayList<>(a);
            all.addAll(b);
            return all;
        }
    }

    /** One understood action: the lamps or blinds it sets and to what, or a text to say. */
    private record Parsed(Map<String, Double> lamps, Map<String, Double> blinds, String say, String echo) {
    }

    RoomAction(Params params) {
        this.params = params;
        for (String lamp : params.lamps()) {
            lampOutputs.put(lamp, output(lamp(lamp)));
            levels.put(lamp, 0.0);
        }
        for (String blind : params.blinds()) {
            blindOutputs.put(blind, output(blind(blind)));
        }
        say = params.speaker() ? output(SAY) : null;
        input(ACTION, this::onAction, v -> refusal(params, v.text()));
    }

    /** The ports of a room with these lamps, blinds and speaker: one output per lamp and per blind. */
    static Ports ports(Params params) {
        List<Ports.Port> more = new ArrayList<>();
        params.lamps().forEach(lamp -> more.add(lamp(lamp)));
        params.blinds().forEach(blind -> more.add(blind(blind)));
        if (params.speaker()) {
            more.add(SAY);
        }
        return Ports.of(ACTION, ECHO, LAMPS).plus(more);
    }

    private static OutputPort<NumberValue> lamp(String name) {
        return OutputPort.of(name, NumberValue.class, Shape.number("", "lamp " + name + "'s level 0..1"));
    }

    private static OutputPort<NumberValue> blind(String name) {
        return OutputPort.of(name, NumberValue.class, Shape.number("", "how far blinds " + name + " are open, 0..1"));
    }

    private static String refusal(Params params, String text) {
        return parse(params, text) != null ? null : "'" + abbreviate(text) + "' is no room action; write '<lamp> on|off|0..1' "
                + "(lamps: " + params.lamps() + "), 'all on|off', '<blinds> open|close|0..1' (blinds: " + params.blinds()
                + ")" + (params.speaker() ? " or 'say <text>'" : "");
    }

    private void onAction(TextValue value, Sample sample) {
        Parsed p = parse(params, value.text());
        if (p == null) {
            if (refused++ == 0) {
                log().warn("{}: {} (further ones only counted)", id(), refusal(params, value.text()));
            }
            return;
        }
        emit(echo, new TextValue(p.echo()));
        p.lamps().forEach((lamp, level) -> {
            levels.put(lamp, level);
            emit(lampOutputs.get(lamp), new NumberValue(level));
        });
        p.blinds().forEach((blind, open) -> emit(blindOutputs.get(blind), new NumberValue(open)));
        if (p.say() != null) {
            emit(say, new TextValue(p.say()));
        }
        if (!p.lamps().isEmpty()) {
            emit(lamps, RecordValue.of(new LampLevels(levels)));
        }
    }

    private static Parsed parse(Params params, String text) {
        String key = text == null ? "" : text.strip().replaceAll("\\s+", " ").toLowerCase(Locale.ROOT);
        if (params.speaker() && key.startsWith("say ")) {
            String words = text.strip().substring(3).strip();
            return new Parsed(Map.of(), Map.of(), words, "say " + words);
        }
        String[] parts = key.split(" ");
        if (parts.length != 2) {
            return null;
        }
        String target = parts[0];
        String how = parts[1];
        if (target.equals("all") || params.lamps().contains(target)) {
            Double level = switch (how) {
                case "on" -> 1.0;
                case "off" -> 0.0;
                default -> fraction(how);
            };
            if (level == null || target.equals("all") && params.lamps().isEmpty()) {
                return null;
            }
            Map<String, Double> set = new LinkedHashMap<>();
            for (String lamp : target.equals("all") ? params.lamps() : List.of(target)) {
                set.put(lamp, level);
            }
            return new Parsed(set, Map.of(), null, key);
        }
        if (params.blinds().contains(target)) {
            Double open = switch (how) {
                case "open" -> 1.0;
                case "close", "closed" -> 0.0;
                default -> fraction(how);
            };
            return open == null ? null : new Parsed(Map.of(), Map.of(target, open), null, key);
        }
        return null;
    }

    private static Double fraction(String text) {
        if (!text.matches("(0|1)?(\\.\\d{1,6})?|[01]")) {
            return null;
        }
        try {
            double v = Double.parseDouble(text);
            return v >= 0 && v <= 1 ? v : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private static String abbreviate(String text) {
        String t = text == null ? "" : text;
        return t.length() <= 40 ? t : t.substring(0, 37) + "...";
    }

    /** Actions from wired methods that were not understood, since start. */
    public long refused() {
        return refused;
    }

    /** Makes {@code room-action} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("room-action", "The actions a control architecture writes to a room: lamps on, off or dimmed, "
                    + "blinds, and the speaker", Params.class, RoomAction::ports, (layer, p) -> new RoomAction(p),
                    Layer.VIRTUAL);
        }
    }
}
