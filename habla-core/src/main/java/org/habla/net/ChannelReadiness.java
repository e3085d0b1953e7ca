package org.habla.net;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.CancelledKeyException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Tells served connections when their non-blocking sockets can be read or written: one selector on one
 * thread for the whole JVM. A {@link ChannelConnection} that finds nothing to read (or no room to write) asks for
 * that readiness and waits; the selector hands it over once and asks no more until asked again.
 *
 * <pre>
 *   reader: read() == 0 --&gt; interest OP_READ --&gt; park ... selector: ready --&gt; interest cleared --&gt; unpark
 * </pre>
 */
final class ChannelReadiness {

    private static final Logger LOG = LoggerFactory.getLogger(ChannelReadiness.class);
    private static volatile ChannelReadiness shared;

    private final Selector selector;

    private ChannelReadiness() throws IOException {
        selector = Selector.open();
        Thread t = new Thread(this::loop, "habla-control-readiness");
        t.setDaemon(true);
        t.start();
    }

    /** The JVM's one instance, started on first use. */
    static ChannelReadiness shared() {
        ChannelReadiness r = shared;
        if (r == null) {
            synchronized (ChannelReadiness.class) {
                r = shared;
                if (r == null) {
                    try {
                        r = new ChannelReadiness();
                    } catch (IOException e) {
                        throw new UncheckedIOException("cannot open a selector for control connections", e);
                    }
                    shared = r;
                }
            }
        }
        return r;
    }

    /** Registers a non-blocking channel, asking for nothing yet; readiness goes to {@code connection}. */
    SelectionKey register(SocketChannel channel, ChannelConnection connection) throws IOException {
        return channel.register(selector, 0, connection);
    }

    /** Makes the selector take a changed interest (or a closed channel) into account now. */
    void wakeup() {
        selector.wakeup();
    }

    private void loop() {
        while (true) {
            try {
                selector.select(this::ready);
            } catch (ClosedSelectorException e) {
                return;
            } catch (IOException | RuntimeException e) {
                LOG.warn("control connections' selector: {}", e.toString());
            }
        }
    }

    private void ready(SelectionKey key) {
        try {
            int ready = key.readyOps();
            key.interestOpsAnd(~ready);
            ((ChannelConnection) key.attachment()).ready(ready);
        } catch (CancelledKeyException e) {
            ((ChannelConnection) key.attachment()).ready(SelectionKey.OP_READ | SelectionKey.OP_WRITE);
        }
    }
}
