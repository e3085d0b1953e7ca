package org.habla.drivers.pcm;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;

/**
 * Both ends of one real TCP connection on loopback: the "device" side a test writes to and reads from, and
 * the driver side handed to a session. Reads on the driver side time out after 2 s so no test can hang.
 */
public final class LoopbackPeer implements AutoCloseable {

    private final Socket device;
    private final Socket driver;
    private final InputStream driverIn;

    public LoopbackPeer() throws IOException {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            driver = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
            server.setSoTimeout(15_000);
            device = server.accept();
        }
        driver.setSoTimeout(15_000);
        device.setSoTimeout(15_000);
        driverIn = new BufferedInputStream(driver.getInputStream());
    }

    /** What the driver reads. */
    public InputStream driverIn() {
        return driverIn;
    }

    /** Where the driver writes. */
    public OutputStream driverOut() throws IOException {
        return driver.getOutputStream();
    }

    /** Writes bytes from the device side, in pieces of {@code piece} bytes, each flushed. */
    public void deviceWrites(byte[] bytes, int piece) throws IOException {
        OutputStream out = device.getOutputStream();
        for (int at = 0; at < bytes.length; at += piece) {
            out.write(bytes, at, Math.min(piece, bytes.length - at));
            out.flush();
        }
    }

    /** What the device has received, exactly {@code n} bytes (waits at most 2 s). */
    public byte[] deviceReads(int n) throws IOException {
        return device.getInputStream().readNBytes(n);
    }

    /** The device closes its side. */
    public void deviceHangsUp() throws IOException {
        device.shutdownOutput();
    }

    @Override
    public void close() throws IOException {
        device.close();
        driver.close();
    }
}
