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
    private final Gui gui;
    private boolean everStarted;

    /**
     * The viewer a behaviour asks the Controller's client to open when it starts ({@code load}) and to close when
     * it stops ({@code close}), as Tekkotsu's {@code Controller::loadGUI}/{@code closeGUI} name it.
     *
     * @param javaClass the TekkotsuMon class ({@code org.tekkotsu.mon.WalkGUI})
     * @param instance  the viewer's instance name, also what {@code close} names ({@code WalkGUI})
     * @param args      the launch arguments, each sent quoted on the fourth line (none: an empty line)
     */
    record Gui(String javaClass, String instance, List<String> args) {
        Gui {
            args = List.copyOf(args);
        }
    }

    private MenuItem(String name, String description, List<MenuItem> children, TekkotsuSocket server, Gui gui) {
        this.name = name;
        this.description = description;
        this.children = List.copyOf(children);
        this.server = server;
        this.gui = gui;
        this.everStarted = server != null && server.isOn();
    }

    static MenuItem menu(String name, String description, List<MenuItem> children) {
        return new MenuItem(name, description, children, null, null);
    }

    /** A behaviour that runs a server socket; {@code gui} is the viewer the robot asks a GUI to open, or null. */
    static MenuItem behavior(String name, String description, TekkotsuSocket server, Gui gui) {
        return new MenuItem(name, description, List.of(), server, gui);
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

    Gui gui() {
        return gui;
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
