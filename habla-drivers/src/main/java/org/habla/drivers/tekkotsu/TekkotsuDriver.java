package org.habla.drivers.tekkotsu;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.Liveness;

/**
 * The driver of a Sony Aibo ERS-7 running Tekkotsu: one connection per Tekkotsu server the params
 * switch on, each with its own session. A channel is offered only when its server's connection is.
 *
 * <pre>
 * connection   port   channels
 * worldstate   10031  ir, buttons, joints, head (reading), accel
 * walk         10050  walk (command, motion)
 * head         10052  head (command)
 * estop        10053  -   (releases the emergency stop; engages it on goodbye)
 * microphone   10070  audio
 * speaker      10071  speaker (command)
 * camera       10011  camera (raw camera over TCP)
 * controller   10020  -   (switches the other servers on; optional: the interface is up without it)
 * </pre>
 */
final class TekkotsuDriver implements Driver {

    /**
     * World state, microphone and raw camera stream every frame (about 32 ms) without being asked: three seconds
     * without a byte means the server is gone. The other servers speak only when spoken to, so for them silence
     * is normal and only TCP tells that they are gone.
     */
    static final Liveness STREAM = Liveness.periodic(Duration.ofSeconds(3));

    private final List<ChannelDescriptor> channels;
    private final List<Connection> connections;

    TekkotsuDriver(TekkotsuParams p) {
        List<ChannelDescriptor> ch = new ArrayList<>();
        List<Connection> conn = new ArrayList<>();
        if (p.worldState()) {
            ch.addAll(TekkotsuChannels.worldState());
            conn.add(new Connection("worldstate", p.worldStatePort(), Set.of(), STREAM, WorldStateSession::new));
        }
        if (p.microphone()) {
            ch.add(TekkotsuChannels.microphone());
            conn.add(new Connection("microphone", p.microphonePort(), Set.of(), STREAM, MicrophoneSession::new));
        }
        if (p.camera()) {
            ch.add(TekkotsuChannels.camera(p.cameraSkip(), p.cameraHeightM()));
            conn.add(new Connection("camera", p.cameraPort(), Set.of(), STREAM, RawCamSession::new));
        }
        if (p.walk()) {
            ch.add(TekkotsuChannels.walk(p));
            WalkSession.WalkLimits limits = new WalkSession.WalkLimits(p.maxForwardMps(), p.maxReverseMps(),
                    p.maxStrafeMps(), p.maxRotateRadps());
            Duration resend = Duration.ofMillis(p.walkResendMs());
            conn.add(new Connection("walk", p.walkPort(), Set.of(TekkotsuChannels.WALK), Liveness.quiet(),
                    () -> new WalkSession(limits, resend)));
        }
        if (p.head()) {
            ch.add(TekkotsuChannels.headCommand());
            conn.add(new Connection("head", p.headPort(), Set.of(TekkotsuChannels.HEAD), Liveness.quiet(),
                    HeadSession::new));
        }
        if (p.speaker()) {
            ch.add(TekkotsuChannels.speaker(p.speakerRateHz()));
            int rate = p.speakerRateHz();
            conn.add(new Connection("speaker", p.speakerPort(), Set.of(TekkotsuChannels.SPEAKER), Liveness.quiet(),
                    () -> new SpeakerSession(rate)));
        }
        if (p.eStop()) {
            boolean release = p.releaseEStop();
            conn.add(new Connection("estop", p.eStopPort(), Set.of(), Liveness.quiet(), () -> new EStopSession(release)));
        }
        if (p.controller()) {
            List<String> commands = ControllerSession.startCommands(p.startServers(),
                    p.camera() ? Optional.of(p.cameraSkip()) : Optional.empty());
            // Optional: it only switches the other servers on, and a robot whose servers run without it still streams.
            conn.add(new Connection("controller", p.controllerPort(), Set.of(), Liveness.quiet(),
                    () -> new ControllerSession(commands)).asOptional());
        }
        this.channels = List.copyOf(ch);
        this.connections = List.copyOf(conn);
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return channels;
    }

    @Override
    public List<Connection> connections() {
        return connections;
    }
}
