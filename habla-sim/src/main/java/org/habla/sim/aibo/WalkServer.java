package org.habla.sim.aibo;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.Socket;

/**
 * The walk remote control (Walk Remote Control, port 10050): 5-byte commands {@code f} (forward),
 * {@code s} (strafe, + left), {@code r} (rotate, + counter-clockwise), each a fraction of the walk's
 * maximum speed. Other letters ({@code 0}–{@code 9}: no-ops and sounds) are ignored. The robot sends
 * nothing back. The body stops the walk 3 s of simulated time after the last command.
 */
final class WalkServer implements TekkotsuSocket.Client {

    private final Ers7Body body;
    private final AiboTime clock;

    WalkServer(Ers7Body body, AiboTime clock) {
        this.body = body;
        this.clock = clock;
    }

    @Override
    public void serve(Socket socket) throws IOException {
        FiveByteInput in = new FiveByteInput(new BufferedInputStream(socket.getInputStream()));
        for (FiveByteInput.Command c = in.next(); c != null; c = in.next()) {
            body.walkCommand(c.letter(), c.value(), clock.nowMs());
        }
    }
}
