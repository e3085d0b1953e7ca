package org.habla.drivers.tekkotsu;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;

/**
 * The base of sessions on Tekkotsu servers that only listen (walk, head, speaker): the robot sends
 * nothing, so their connections are declared quiet and silence never ends the link; bytes that do arrive
 * are counted as malformed and dropped; the robot closing the socket ends it.
 */
abstract class CommandOnlySession implements LinkSession {

    private final String server;

    CommandOnlySession(String server) {
        this.server = server;
    }

    @Override
    public final void readNext(InputStream in, ReadingSink sink) throws IOException {
        byte[] buffer = new byte[512];
        int n = in.read(buffer);
        if (n < 0) {
            throw new EOFException("the " + server + " closed the connection");
        }
        if (n > 0) {
            sink.malformed("the " + server + " sent " + n + " unexpected bytes (it should send nothing); dropped");
        }
    }
}
