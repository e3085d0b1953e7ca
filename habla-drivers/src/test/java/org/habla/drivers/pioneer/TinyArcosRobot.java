package org.habla.drivers.pioneer;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A tiny ARCOS robot on a loopback port, just enough for handshake tests: it answers SYNC0 and SYNC1 with
 * echoes and SYNC2 with its name, class and subclass, records every packet it receives, and sends what a
 * test tells it to. Optionally it starts "still open" from an earlier client and answers SYNC0 with a SIP
 * until it gets a CLOSE. One client at a time.
 */
final class TinyArcosRobot implements AutoCloseable {

    private final ServerSocket server;
    private final BlockingQueue<ArcosPacket> received = new LinkedBlockingQueue<>();
    private final Thread thread;
    private volatile boolean stillOpen;
    private volatile boolean silent;
    private volatile Socket client;

    TinyArcosRobot() throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        thread = Thread.ofPlatform().daemon().name("tiny-arcos-robot").start(this::serve);
    }

    /** Starts as if an earlier client never sent CLOSE. */
    TinyArcosRobot stillOpen() {
        stillOpen = true;
        return this;
    }

    /** Never answers anything. */
    TinyArcosRobot silent() {
        silent = true;
        return this;
    }

    int port() {
        return server.getLocalPort();
    }

    /** The next packet the robot received, waiting at most 15 s. */
    ArcosPacket nextReceived() throws InterruptedException {
        ArcosPacket p = received.poll(15, TimeUnit.SECONDS);
        if (p == null) {
            throw new AssertionError("the robot received nothing within 15 s");
        }
        return p;
    }

    /** Sends raw bytes to the client. */
    void send(byte[] bytes) throws IOException {
        OutputStream out = client.getOutputStream();
        out.write(bytes);
        out.flush();
    }

    /** Closes the client's connection. */
    void hangUp() throws IOException {
        client.close();
    }

    private void serve() {
        try (Socket s = server.accept()) {
            client = s;
            InputStream in = s.getInputStream();
            OutputStream out = s.getOutputStream();
            ArcosPacketDecoder decoder = new ArcosPacketDecoder();
            byte[] buf = new byte[256];
            int n;
            while ((n = in.read(buf)) > 0) {
                decoder.push(buf, 0, n, new ArcosPacketDecoder.Listener() {
                    @Override
                    public void packet(ArcosPacket packet) {
                        received.add(packet);
                        try {
                            answer(packet, out);
                        } catch (IOException e) {
                            throw new RuntimeException(e);
                        }
                    }

                    @Override
                    public void malformed(String what) {
                        throw new AssertionError("the driver sent a malformed packet: " + what);
                    }
                });
            }
        } catch (IOException | RuntimeException e) {
            // the test ended the connection
        }
    }

    private boolean open;

    private void answer(ArcosPacket p, OutputStream out) throws IOException {
        if (silent) {
            return;
        }
        if (stillOpen) {
            if (p.type() == ArcosCommand.CLOSE.number()) {
                stillOpen = false;
            } else {
                out.write(CapturedSip.wire());
            }
            out.flush();
            return;
        }
        if (open) {
            return;
        }
        switch (p.type()) {
            case 0 -> out.write(ArcosCommand.SYNC0.packet().toWire());
            case 1 -> out.write(ArcosCommand.SYNC1.packet().toWire());
            case 2 -> {
                out.write(ArcosPacket.of(Hex.bytes("02 54 69 6E 79 00 50 69 6F 6E 65 65 72 00 70 32 64 78 00")).toWire());
                open = true;
            }
            default -> {
            }
        }
        out.flush();
    }

    @Override
    public void close() throws IOException {
        server.close();
        Socket c = client;
        if (c != null) {
            c.close();
        }
        thread.interrupt();
    }
}
