package org.habla.graph;

import java.io.IOException;
import java.net.Socket;
import jdk.net.ExtendedSocketOptions;
import org.habla.config.Reconnect;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The TCP socket of a link to a robot's server or to a worker: no Nagle delay, and TCP keep-alive with the
 * interface's short idle time, probe interval and probe count, so a peer whose host vanishes without closing
 * the connection is noticed even while the stream is quiet. Where the system offers no per-socket keep-alive
 * settings, keep-alive runs with the system's own (usually two hours) and that is logged once.
 */
final class LinkSocket {

    private static final Logger LOG = LoggerFactory.getLogger(LinkSocket.class);
    private static volatile boolean warnedUnsupported;

    private LinkSocket() {
    }

    /** A new, unconnected socket with the link's options set. */
    static Socket create(Reconnect.TcpKeepAlive keepAlive) throws IOException {
        Socket s = new Socket();
        s.setTcpNoDelay(true);
        s.setKeepAlive(true);
        if (s.supportedOptions().contains(ExtendedSocketOptions.TCP_KEEPIDLE)
                && s.supportedOptions().contains(ExtendedSocketOptions.TCP_KEEPINTERVAL)
                && s.supportedOptions().contains(ExtendedSocketOptions.TCP_KEEPCOUNT)) {
            s.setOption(ExtendedSocketOptions.TCP_KEEPIDLE, keepAlive.idleS());
            s.setOption(ExtendedSocketOptions.TCP_KEEPINTERVAL, keepAlive.intervalS());
            s.setOption(ExtendedSocketOptions.TCP_KEEPCOUNT, keepAlive.count());
        } else if (!warnedUnsupported) {
            warnedUnsupported = true;
            LOG.warn("this system does not let HABLA set TCP keep-alive times per socket: a robot or worker whose "
                    + "host vanishes without closing is noticed only after the system's keep-alive time");
        }
        return s;
    }
}
