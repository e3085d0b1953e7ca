// Over 300 lines, on purpose: the Controller's whole menu protocol, one command per case, over one menu state.
package org.habla.sim.aibo;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;

/**
 * The Controller's menu protocol (port 10020), through which a client switches the other servers on.
 * Commands, one per line ({@code ;} separates several, a trailing {@code \r} is dropped):
 * {@code !refresh}, {@code !reset}, {@code !cancel}, {@code !next}, {@code !prev}, {@code !hilight n…},
 * {@code !select} (the highlighted items), {@code !select "<displayed name>"} (searched depth-first from
 * the root), {@code !root a b …} (descend by name prefix or index), {@code !set key=value},
 * {@code !hello}, {@code !dump_stack}, {@code !msg}/{@code !post}/{@code !input} (accepted, no effect
 * here), and plain text (an item of the current menu by index or name prefix).
 *
 * <p>Replies are Tekkotsu's line messages: {@code refresh} blocks (title, item count, then per item its
 * number of sub-items, highlight, displayed name, extra description lines, description), {@code push},
 * {@code pop}, {@code status}, {@code hello}, {@code stack_dump}, and {@code load}/{@code close} when a
 * server with a viewer starts or stops. Selecting a behaviour toggles it.
 */
final class ControllerServer implements TekkotsuSocket.Client {

    private static final int MAX_LINE_BYTES = 4_096;

    private final MenuItem root;
    private final RobotSettings settings;
    private final AtomicLong hellos = new AtomicLong();

    ControllerServer(MenuItem root, RobotSettings settings) {
        this.root = root;
        this.settings = settings;
    }

    @Override
    public void serve(Socket socket) throws IOException {
        Session session = new Session(socket.getOutputStream());
        LineFramer lines = new LineFramer(socket.getInputStream(), MAX_LINE_BYTES);
        session.refresh();
        session.flush();
        while (true) {
            try {
                String line = lines.readText(StandardCharsets.UTF_8);
                if (line == null) {
                    return;
                }
                for (String command : ShellWords.commands(line)) {
                    session.take(command);
                }
            } catch (FrameException e) {
                if (e.fatal()) {
                    return;
                }
                session.status("line longer than " + MAX_LINE_BYTES + " bytes ignored");
            }
            session.flush();
        }
    }

    /** One client's place in the menus. */
    private final class Session {
        private final OutputStream out;
        private final StringBuilder pending = new StringBuilder();
        private final Deque<MenuItem> stack = new ArrayDeque<>();
        private final Set<Integer> highlighted = new HashSet<>();

        Session(OutputStream out) {
            this.out = out;
            stack.push(root);
        }

        void take(String command) {
            List<String> w = ShellWords.words(command);
            if (w.isEmpty()) {
                return;
            }
            String verb = w.get(0);
            List<String> args = w.subList(1, w.size());
            switch (verb) {
                case "!refresh" -> refresh();
                case "!reset" -> {
                    stack.clear();
                    stack.push(root);
                    highlighted.clear();
                    refresh();
                }
                case "!cancel" -> {
                    if (stack.size() > 1) {
                        stack.pop();
                        highlighted.clear();
                        send("pop");
                    }
                    refresh();
                }
                case "!next", "!prev" -> move(verb.equals("!next") ? 1 : -1);
                case "!hilight" -> hilight(args);
                case "!select" -> select(args);
                case "!root" -> descend(args);
                case "!set" -> set(String.join(" ", args));
                case "!hello" -> send("hello", Long.toString(hellos.incrementAndGet()));
                case "!dump_stack" -> dumpStack();
                case "!msg", "!post", "!input" -> status(verb + " accepted; the simulated Aibo has no behaviour "
                        + "listening");
                default -> {
                    if (verb.startsWith("!")) {
                        status("unknown command " + Abbreviation.of(verb));
                    } else {
                        Optional<MenuItem> item = child(stack.peek(), String.join(" ", w));
                        if (item.isPresent()) {
                            activate(item.get());
                        } else {
                            status("no item '" + Abbreviation.of(command) + "' in " + stack.peek().name());
                        }
                        refresh();
                    }
                }
            }
        }

        private void move(int step) {
            int n = stack.peek().children().size();
            int at = highlighted.isEmpty() ? (step > 0 ? -1 : 0) : highlighted.iterator().next();
            highlighted.clear();
            if (n > 0) {
                highlighted.add(Math.floorMod(at + step, n));
            }
            refresh();
        }

        private void hilight(List<String> args) {
            highlighted.clear();
            for (String a : args) {
                try {
                    int i = Integer.parseInt(a);
                    if (i >= 0 && i < stack.peek().children().size()) {
                        highlighted.add(i);
                    }
                } catch (NumberFormatException e) {
                    status("!hilight takes item numbers, not '" + Abbreviation.of(a) + "'");
                }
            }
            refresh();
        }

        private void select(List<String> args) {
            if (args.isEmpty()) {
                List<MenuItem> items = stack.peek().children();
                for (int i : List.copyOf(highlighted)) {
                    activate(items.get(i));
                }
            } else {
                String name = String.join(" ", args);
                Optional<MenuItem> found = find(root, name);
                if (found.isEmpty()) {
                    status("no menu item is displayed as '" + Abbreviation.of(name) + "'");
                } else {
                    activate(found.get());
                }
            }
            refresh();
        }

        private void descend(List<String> args) {
            stack.clear();
            stack.push(root);
            highlighted.clear();
            for (String a : args) {
                Optional<MenuItem> item = child(stack.peek(), a);
                if (item.isEmpty()) {
                    status("no item '" + Abbreviation.of(a) + "' in " + stack.peek().name());
                    break;
                }
                activate(item.get());
            }
            refresh();
        }

        private void set(String assignment) {
            int eq = assignment.indexOf('=');
            if (eq <= 0) {
                status("!set takes section.key=value");
                return;
            }
            settings.set(assignment.substring(0, eq), assignment.substring(eq + 1)).ifPresent(this::status);
        }

        private void activate(MenuItem item) {
            if (item.isMenu()) {
                if (!item.children().isEmpty()) {
                    stack.push(item);
                    highlighted.clear();
                    send("push");
                }
                return;
            }
            boolean running = item.toggle();
            MenuItem.Gui gui = item.gui();
            if (gui != null) {
                if (running) {
                    send("load", gui.javaClass(), gui.instance(), Integer.toString(item.server().port()),
                            quoted(gui.args()));
                } else {
                    send("close", gui.instance());
                }
            }
        }

        /** Launch arguments as Tekkotsu writes them: each in double quotes ({@code \\ " newline} escaped) and a space. */
        private static String quoted(List<String> args) {
            StringBuilder b = new StringBuilder();
            for (String a : args) {
                b.append('"');
                for (char c : a.toCharArray()) {
                    if (c == '\\' || c == '"' || c == '\n') {
                        b.append('\\');
                    }
                    b.append(c);
                }
                b.append("\" ");
            }
            return b.toString();
        }

        private void dumpStack() {
            List<String> titles = new ArrayList<>();
            stack.descendingIterator().forEachRemaining(m -> titles.add(m.name()));
            List<String> lines = new ArrayList<>();
            lines.add("stack_dump");
            lines.add(Integer.toString(titles.size()));
            lines.addAll(titles);
            send(lines.toArray(String[]::new));
        }

        void refresh() {
            MenuItem menu = stack.peek();
            List<String> lines = new ArrayList<>(List.of("refresh", menu.name(),
                    Integer.toString(menu.children().size())));
            for (int i = 0; i < menu.children().size(); i++) {
                MenuItem item = menu.children().get(i);
                String[] description = item.description().split("\n", -1);
                lines.add(Integer.toString(item.children().size()));
                lines.add(highlighted.contains(i) ? "1" : "0");
                lines.add(item.displayedName());
                lines.add(Integer.toString(description.length - 1));
                lines.addAll(List.of(description));
            }
            send(lines.toArray(String[]::new));
        }

        void status(String text) {
            String[] lines = text.split("\n", -1);
            List<String> out = new ArrayList<>(List.of("status", Integer.toString(lines.length - 1)));
            out.addAll(List.of(lines));
            send(out.toArray(String[]::new));
        }

        private void send(String... lines) {
            for (String l : lines) {
                pending.append(l).append('\n');
            }
        }

        void flush() throws IOException {
            out.write(pending.toString().getBytes(StandardCharsets.UTF_8));
            out.flush();
            pending.setLength(0);
        }
    }

    /** Depth-first from {@code menu}: the item displayed exactly as {@code name}. */
    private static Optional<MenuItem> find(MenuItem menu, String name) {
        for (MenuItem c : menu.children()) {
            if (c.displayedName().equals(name)) {
                return Optional.of(c);
            }
            Optional<MenuItem> deeper = find(c, name);
            if (deeper.isPresent()) {
                return deeper;
            }
        }
        return Optional.empty();
    }

    /** A child of {@code menu} by index, else by name prefix (case-sensitive first, then not). */
    private static Optional<MenuItem> child(MenuItem menu, String key) {
        List<MenuItem> items = menu.children();
        try {
            int i = Integer.parseInt(key.strip());
            return i >= 0 && i < items.size() ? Optional.of(items.get(i)) : Optional.empty();
        } catch (NumberFormatException e) {
            // a name
        }
        for (MenuItem c : items) {
            if (c.name().startsWith(key) || c.displayedName().startsWith(key)) {
                return Optional.of(c);
            }
        }
        String lower = key.toLowerCase(Locale.ROOT);
        for (MenuItem c : items) {
            if (c.name().toLowerCase(Locale.ROOT).startsWith(lower)) {
                return Optional.of(c);
            }
        }
        return Optional.empty();
    }
}
