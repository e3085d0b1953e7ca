package org.habla.sim.aibo;

import java.util.List;

/**
 * One item of the Controller's menu tree: a sub-menu (with children) or a behaviour that a selection
 * toggles. A behaviour's displayed name carries its state, as Tekkotsu's BehaviorSwitchControl shows it:
 * the plain name when it was never started, {@code #name} while it runs, {@code -name} once stopped.
 */
final class MenuItem {

    private final String name;
    private final String description;
    private final List<MenuItem> children;
    private final TekkotsuSocket server;
    private final String guiClass;
    private boolean everStarted;

    private MenuItem(String name, String description, List<MenuItem> children, TekkotsuSocket server,
            String guiClass) {
        this.name = name;
        this.description = description;
        this.children = List.copyOf(children);
        this.server = server;
        this.guiClass = guiClass;
        this.everStarted = server != null && server.isOn();
    }

    static MenuItem menu(String name, String description, List<MenuItem> children) {
        return new MenuItem(name, description, children, null, null);
    }

    /** A behaviour that runs a server socket; {@code guiClass} is the viewer the robot asks a GUI to open, or null. */
    static MenuItem behavior(String name, String description, TekkotsuSocket server, String guiClass) {
        return new MenuItem(name, description, List.of(), server, guiClass);
    }

    String name() {
        return name;
    }

    String description() {
        return description;
    }

    List<MenuItem> children() {
        return children;
    }

    boolean isMenu() {
        return server == null;
    }

    TekkotsuSocket server() {
        return server;
    }

    String guiClass() {
        return guiClass;
    }

    synchronized String displayedName() {
        if (server == null) {
            return name;
        }
        return server.isOn() ? "#" + name : everStarted ? "-" + name : name;
    }

    /** Starts a stopped behaviour or stops a running one; returns whether it now runs. */
    synchronized boolean toggle() {
        boolean run = !server.isOn();
        server.switchOn(run);
        everStarted |= run;
        return run;
    }
}
