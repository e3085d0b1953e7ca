package org.habla.sim.aibo;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.LongFunction;

/**
 * The simulated Aibo's Tekkotsu servers and the Controller menu that switches them. At boot only the
 * Controller and the emergency-stop control run, as on the robot; the rest are items of the
 * {@code TekkotsuMon} menu (Tekkotsu 4.0 names):
 * <pre>
 * Head Remote Control      10052   head angles in
 * Walk Remote Control      10050   walk speeds in
 * EStopControllerBehavior  10053   running at boot
 * World State Serializer   10031   joints, IR, buttons out every 32 ms
 * Raw Cam Server           10011   JPEG frames out (TCP)
 * Microphone Server        10070   stereo 16 kHz PCM out
 * Speaker Server           10071   mono PCM in
 * </pre>
 */
public final class TekkotsuServers implements AutoCloseable {

    private final List<TekkotsuSocket> sockets = new ArrayList<>();
    private final TekkotsuSocket controller;
    private final TekkotsuSocket eStop;
    private final TekkotsuSocket worldState;
    private final TekkotsuSocket walk;
    private final TekkotsuSocket head;
    private final TekkotsuSocket microphone;
    private final TekkotsuSocket speaker;
    private final TekkotsuSocket rawCam;

    /**
     * Binds every server's port on loopback.
     *
     * @param views what the camera sees at a simulated time in ms
     */
    public TekkotsuServers(TekkotsuPorts ports, AiboTime time, Ers7Body body, Microphone mic, SpeakerLog said,
            LongFunction<CameraView> views) throws IOException {
        RobotSettings settings = new RobotSettings();
        try {
            eStop = add(new TekkotsuSocket("e-stop", ports.eStop(), true, new EStopServer(body)));
            worldState = add(new TekkotsuSocket("world-state", ports.worldState(), false,
                    new WorldStateServer(body, time, settings)));
            walk = add(new TekkotsuSocket("walk", ports.walk(), false, new WalkServer(body, time)));
            head = add(new TekkotsuSocket("head", ports.head(), false, new HeadServer(body)));
            microphone = add(new TekkotsuSocket("microphone", ports.microphone(), false,
                    new MicrophoneServer(mic, time)));
            speaker = add(new TekkotsuSocket("speaker", ports.speaker(), false, new SpeakerServer(said, time)));
            rawCam = add(new TekkotsuSocket("raw-camera", ports.rawCam(), false,
                    new RawCamServer(views, body, time, settings)));
            MenuItem root = menu();
            controller = add(new TekkotsuSocket("controller", ports.controller(), true,
                    new ControllerServer(root, settings)));
            sockets.forEach(TekkotsuSocket::releaseReservation);
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
    }

    private TekkotsuSocket add(TekkotsuSocket s) {
        sockets.add(s);
        return s;
    }

    private MenuItem menu() {
        MenuItem mon = MenuItem.menu("TekkotsuMon", "Servers for remote monitoring and control", List.of(
                MenuItem.behavior("Head Remote Control", "Listens for head angles", head,
                        new MenuItem.Gui("org.tekkotsu.mon.HeadPointGUI", "HeadPointGUI", List.of())),
                MenuItem.behavior("Walk Remote Control", "Listens for walk speeds", walk,
                        new MenuItem.Gui("org.tekkotsu.mon.WalkGUI", "WalkGUI", List.of())),
                MenuItem.behavior("EStopControllerBehavior", "Emergency stop control", eStop, null),
                MenuItem.behavior("World State Serializer", "Sends joints, sensors, buttons and duties", worldState,
                        null),
                // The simulator serves the camera over TCP only (it refuses !set vision.rawcam.transport=UDP).
                MenuItem.behavior("Raw Cam Server", "Sends camera images", rawCam, new MenuItem.Gui(
                        "org.tekkotsu.mon.VisionGUI", "RawVisionGUI", List.of("raw", Integer.toString(rawCam.port()), "tcp"))),
                MenuItem.behavior("Microphone Server", "Sends microphone audio", microphone, null),
                MenuItem.behavior("Speaker Server", "Plays audio it receives", speaker, null)));
        List<MenuItem> rootItems = new ArrayList<>();
        for (String name : List.of("Mode Switch", "Background Behaviors")) {
            rootItems.add(MenuItem.menu(name, "not simulated", List.of()));
        }
        rootItems.add(mon);
        for (String name : List.of("Status Reports", "File Access", "Vision Pipeline", "Shutdown?", "Help")) {
            rootItems.add(MenuItem.menu(name, "not simulated", List.of()));
        }
        return MenuItem.menu("Root Control", "", rootItems);
    }

    /** The ports actually bound (free ports resolved). */
    public TekkotsuPorts ports() {
        return new TekkotsuPorts(controller.port(), eStop.port(), worldState.port(), walk.port(), head.port(),
                microphone.port(), speaker.port(), rawCam.port());
    }

    @Override
    public void close() {
        for (TekkotsuSocket s : sockets) {
            s.close();
        }
    }
}
