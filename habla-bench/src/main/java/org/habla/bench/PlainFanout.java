package org.habla.bench;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The baseline for the fan-out crowd round: a plain Java relay that reads the robot's lines, parses each, encodes
 * one sample line and writes the same bytes to every connected client, starting one client further along each
 * time as the daemon does. Either the reading thread writes to every socket itself, one after another (the least
 * a relay can do per client: one send each), or each client has a writer on a virtual thread fed by a queue, as
 * the daemon's clients have. No engine, no outbox, no status: what is left is the sockets and the threads. The
 * reading thread writes without blocking; a client whose socket does not take a whole line (one that does not
 * read) gets nothing more, so that it cannot hold up the others.
 */
final class PlainFanout implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    /** How the relay writes to its clients. */
    enum Writers {
        /** The reading thread writes each client's socket itself. */
        ONE_THREAD("plain fan-out, the reading thread writes every socket"),
        /** A writer on a virtual thread per client, each woken by its queue. */
        VIRTUAL_EACH("plain fan-out, a virtual writer per client");

        final String title;

        Writers(String title) {
            this.title = title;
        }
    }

    /** One client's socket and, with {@link Writers#VIRTUAL_EACH}, its queue. */
    private static final class Client {
        final SocketChannel channel;
        final BlockingQueue<ByteBuffer> queue;
        boolean behind;

        Client(SocketChannel channel, BlockingQueue<ByteBuffer> queue) {
            this.channel = channel;
            this.queue = queue;
        }
    }

    private final ServerSocketChannel server;
    private final int robotPort;
    private final Writers writers;
    private final List<Client> clients = new CopyOnWriteArrayList<>();
    private final Thread acceptor;
    private volatile Thread relay;
    private volatile Socket robot;
    private volatile boolean closed;

    PlainFanout(int robotPort, Writers writers) throws IOException {
        this.robotPort = robotPort;
        this.writers = writers;
        server = ServerSocketChannel.open();
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        acceptor = Thread.ofPlatform().name("plain-fanout-accept").daemon().start(this::accept);
    }

    int port() {
        return ((InetSocketAddress) server.socket().getLocalSocketAddress()).getPort();
    }

    /** Connects to the robot and starts relaying to whoever is connected. */
    void start() {
        relay = Thread.ofPlatform().name("plain-fanout-relay").daemon().start(this::relay);
    }

    private void accept() {
        try {
            while (!closed) {
                SocketChannel ch = server.accept();
                ch.socket().setTcpNoDelay(true);
                BlockingQueue<ByteBuffer> queue = null;
                if (writers == Writers.VIRTUAL_EACH) {
                    BlockingQueue<ByteBuffer> q = new ArrayBlockingQueue<>(256);
                    queue = q;
                    Thread.ofVirtual().name("plain-fanout-writer").start(() -> write(ch, q));
                } else {
                    ch.configureBlocking(false);
                }
                clients.add(new Client(ch, queue));
            }
        } catch (IOException e) {
            // closed
        }
    }

    private void relay() {
        try (Socket r = new Socket(InetAddress.getLoopbackAddress(), robotPort)) {
            r.setTcpNoDelay(true);
            robot = r;
            BufferedReader in = new BufferedReader(new InputStreamReader(r.getInputStream(), StandardCharsets.UTF_8));
            in.readLine();   // the robot's hello
            long seq = 0;
            int turn = 0;
            for (String line = in.readLine(); line != null && !closed; line = in.readLine()) {
                byte[] bytes = PlainRelay.sampleLine(JSON.readTree(line), ++seq).getBytes(StandardCharsets.UTF_8);
                Object[] all = clients.toArray();
                int n = all.length;
                for (int i = 0; i < n; i++) {
                    Client c = (Client) all[(turn + i) % n];
                    if (c.queue == null) {
                        if (!c.behind) {
                            c.behind = !sendAtOnce(c.channel, bytes);
                        }
                    } else if (!c.queue.offer(ByteBuffer.wrap(bytes))) {
                        c.queue.poll();   // a client that does not read loses its oldest, as in the daemon
                        c.queue.offer(ByteBuffer.wrap(bytes));
                    }
                }
                turn = n == 0 ? 0 : (turn + 1) % n;
            }
        } catch (IOException e) {
            // closed
        }
    }

    /** A client's writer: sends what its queue holds until the client goes away. */
    private static void write(SocketChannel channel, BlockingQueue<ByteBuffer> queue) {
        try {
            while (true) {
                ByteBuffer bytes = queue.take();
                while (bytes.hasRemaining()) {
                    channel.write(bytes);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            // that client went away (or the relay closed its socket)
        }
    }

    /** Writes {@code bytes} if the socket takes them all now; false if it did not (or the client is gone). */
    private static boolean sendAtOnce(SocketChannel channel, byte[] bytes) {
        try {
            return channel.write(ByteBuffer.wrap(bytes)) == bytes.length;
        } catch (IOException e) {
            return false;
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        server.close();
        Socket r = robot;
        if (r != null) {
            r.close();
        }
        for (Client c : clients) {
            c.channel.close();
        }
        for (Thread t : new Thread[] {acceptor, relay}) {
            if (t != null) {
                try {
                    t.join(2_000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }
}
