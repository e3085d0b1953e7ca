package org.habla.drivers.tekkotsu;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The params of a {@code tekkotsu} interface: which of the Aibo's Tekkotsu servers to open and on
 * which ports, the walk's maximum speeds, and what to switch on through the controller.
 */
public record TekkotsuParams(
        @Param(value = "Open the World State Serializer (joints, ir, accel, buttons, head).", defaultValue = "true")
        boolean worldState,
        @Param(value = "Port of the World State Serializer.", defaultValue = "10031", min = 1, max = 65_535)
        int worldStatePort,
        @Param(value = "Open the walk remote control (the walk command channel).", defaultValue = "true")
        boolean walk,
        @Param(value = "Port of the walk remote control.", defaultValue = "10050", min = 1, max = 65_535)
        int walkPort,
        @Param(value = "Open the head remote control (the head command channel).", defaultValue = "true")
        boolean head,
        @Param(value = "Port of the head remote control.", defaultValue = "10052", min = 1, max = 65_535)
        int headPort,
        @Param(value = "Open the emergency-stop control.", defaultValue = "true")
        boolean eStop,
        @Param(value = "Port of the emergency-stop control.", defaultValue = "10053", min = 1, max = 65_535)
        int eStopPort,
        @Param(value = "Send 'start' to the emergency-stop control on connecting (the robot boots stopped).",
                defaultValue = "true")
        boolean releaseEStop,
        @Param(value = "Open the microphone server (the audio channel).", defaultValue = "true")
        boolean microphone,
        @Param(value = "Port of the microphone server.", defaultValue = "10070", min = 1, max = 65_535)
        int microphonePort,
        @Param(value = "Open the speaker server (the speaker command channel).", defaultValue = "true")
        boolean speaker,
        @Param(value = "Port of the speaker server.", defaultValue = "10071", min = 1, max = 65_535)
        int speakerPort,
        @Param(value = "Sample rate sent to the speaker server; other rates are resampled.", unit = "Hz",
                defaultValue = "16000", min = 1_000, max = 65_535)
        int speakerRateHz,
        @Param(value = "Open the raw camera server over TCP (the camera channel).", defaultValue = "true")
        boolean camera,
        @Param(value = "Port of the raw camera server.", defaultValue = "10011", min = 1, max = 65_535)
        int cameraPort,
        @Param(value = "Resolution skip the raw camera is set to "
                + "(0 = 416x320, 1 = 208x160, 2 = 104x80, 3 = 52x40, 4 = 26x20).",
                defaultValue = "2", min = 0, max = 4)
        int cameraSkip,
        @Param(value = "Height of the camera above the floor when standing.", unit = "m", defaultValue = "0.2",
                greaterThan = 0)
        double cameraHeightM,
        @Param(value = "Open the controller (menu) server to switch the other servers on.", defaultValue = "true")
        boolean controller,
        @Param(value = "Port of the controller (menu) server.", defaultValue = "10020", min = 1, max = 65_535)
        int controllerPort,
        @Param(value = "Menu items to switch on through the controller",
                defaultNote = "the items of the servers opened above, under their Tekkotsu 4.0 and 5.x names")
        List<String> startServers,
        @Param(value = "Walk speed at forward fraction 1.", unit = "m/s", defaultValue = "0.18", greaterThan = 0)
        double maxForwardMps,
        @Param(value = "Walk speed at forward fraction -1.", unit = "m/s", defaultValue = "0.18", greaterThan = 0)
        double maxReverseMps,
        @Param(value = "Walk speed at strafe fraction 1.", unit = "m/s", defaultValue = "0.14", greaterThan = 0)
        double maxStrafeMps,
        @Param(value = "Turn rate at rotate fraction 1.", unit = "rad/s", defaultValue = "1.8", greaterThan = 0)
        double maxRotateRadps,
        @Param(value = "How often the standing walk command is re-sent (the robot stops after 3 s without one).",
                unit = "ms", defaultValue = "1000", min = 100, max = 2_500)
        int walkResendMs) {

    public TekkotsuParams {
        if (startServers != null && startServers.contains(null)) {
            throw new IllegalArgumentException("startServers must not contain null");
        }
        startServers = startServers == null ? defaultServers(worldState, walk, head, microphone, speaker, camera)
                : List.copyOf(startServers);
        for (String name : startServers) {
            if (name.isBlank() || name.contains("\"") || name.contains("\n") || name.contains("\\")) {
                throw new IllegalArgumentException("startServers entry '" + name
                        + "' must be a menu item name without quotes, backslashes or line breaks");
            }
        }
        checkDistinctPorts(List.of(new PortUse(worldState, "worldStatePort", worldStatePort),
                new PortUse(walk, "walkPort", walkPort), new PortUse(head, "headPort", headPort),
                new PortUse(eStop, "eStopPort", eStopPort),
                new PortUse(microphone, "microphonePort", microphonePort),
                new PortUse(speaker, "speakerPort", speakerPort), new PortUse(camera, "cameraPort", cameraPort),
                new PortUse(controller, "controllerPort", controllerPort)));
    }

    /** Every default. */
    public static TekkotsuParams defaults() {
        return ParamsJson.defaults(TekkotsuParams.class);
    }

    /** The menu items of the enabled servers: Tekkotsu 4.0 names, then the 5.x names where they differ. */
    private static List<String> defaultServers(boolean worldState, boolean walk, boolean head, boolean microphone,
            boolean speaker, boolean camera) {
        List<String> names = new ArrayList<>();
        if (worldState) {
            names.add("World State Serializer");
        }
        if (walk) {
            names.addAll(List.of("Walk Remote Control", "WalkController"));
        }
        if (head) {
            names.addAll(List.of("Head Remote Control", "HeadController"));
        }
        if (microphone) {
            names.add("Microphone Server");
        }
        if (speaker) {
            names.add("Speaker Server");
        }
        if (camera) {
            names.addAll(List.of("Raw Cam Server", "RawCam"));
        }
        return List.copyOf(names);
    }

    private record PortUse(boolean on, String name, int port) {
    }

    private static void checkDistinctPorts(List<PortUse> uses) {
        Map<Integer, String> used = new HashMap<>();
        for (PortUse u : uses) {
            String other = u.on ? used.putIfAbsent(u.port, u.name) : null;
            if (other != null) {
                throw new IllegalArgumentException(u.name + " and " + other + " are both " + u.port
                        + "; each server needs its own port");
            }
        }
    }
}
