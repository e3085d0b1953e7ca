package org.habla.sim.aibo;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.Socket;

/**
 * The head remote control (Head Remote Control, port 10052): 5-byte commands {@code t} (tilt),
 * {@code p} (pan), {@code r} (nod on the ERS-7), each v in -1..1 setting the joint's target to
 * |v| × (v &gt; 0 ? max : min). The head then moves there at its speed limits and holds it; there is
 * no time-out and no reply.
 */
final class HeadServer implements TekkotsuSocket.Client {

    private final Ers7Body body;

    HeadServer(Ers7Body body) {
        this.body = body;
    }

    @Override
    public void serve(Socket socket) throws IOException {
        FiveByteInput in = new FiveByteInput(new BufferedInputStream(socket.getInputStream()));
        for (FiveByteInput.Command c = in.next(); c != null; c = in.next()) {
            body.headCommand(c.letter(), c.value());
        }
    }
}
