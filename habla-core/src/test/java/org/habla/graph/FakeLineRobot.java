package org.habla.graph;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** A robot on loopback that speaks {@link LineDriver}'s protocol and records what it is told. */
final class FakeLineRobot implements AutoCloseable {

    final BlockingQueue<String> received = new LinkedBlockingQueue<>();
    private final ServerSocket server;
    private volatile Socket client;
    private volatile OutputStream out;
    private final Thread acceptor;

    FakeLineRobot(int port) throws IOException {
        server = new ServerSocket();
        server.setReuseAddress(true);
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        acceptor = Thread.ofVirtual().start(this::accept);
    }

    int port() {
        return server.getLocalPort();
    }

    private void accept() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                InputStream in = new BufferedInputStream(s.getInputStream());
                String hello = LineDriver.readLine(in);
                if (!hello.equals("hello")) {
                    continue;
                }
                out = s.getOutputStream();
                client = s;
                send("ready");
                while (true) {
                    String line = LineDriver.readLine(in);
                    if (!line.equals("ping")) {
                        received.add(line);
                    }
                }
            } catch (IOException e) {
                client = null;
                out = null;
            }
        }
    }

    boolean connected() {
        return client != null;
    }

    /** Waits up to {@code millis} for a client. */
    boolean awaitClient(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (!connected() && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        return connected();
    }

    synchronized void send(String line) throws IOException {
        OutputStream o = out;
        if (o == null) {
            throw new IOException("no client");
        }
        o.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        o.flush();
    }

    /** The next line received other than pings, or null after {@code millis}. */
    String next(long millis) throws InterruptedException {
        return received.poll(millis, TimeUnit.MILLISECONDS);
    }

    @Override
    public void close() throws IOException {
        server.close();
        Socket c = client;
        if (c != null) {
            c.close();
        }
        try {
            acceptor.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
