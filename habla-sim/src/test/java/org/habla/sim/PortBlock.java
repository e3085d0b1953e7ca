package org.habla.sim;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.concurrent.ThreadLocalRandom;

/**
 * A port offset for tests that run a whole robot set-up: every port the simulators, the daemon and its
 * sockets use (their defaults plus the offset) is free when it is chosen.
 */
public final class PortBlock {

    private static final int[] DEFAULTS = {7001, 7002, 7003, 7004, 7010, 7011, 7012, 7013, 7098, 7099, 7600, 8101, 8110, 8120,
        8111, 8199, 10011, 10020, 10031, 10050, 10052, 10053, 10070, 10071, 10199};

    private PortBlock() {
    }

    public static int freeOffset() throws IOException {
        for (int attempt = 0; attempt < 50; attempt++) {
            // Every port of the block below the kernel's usual ephemeral range (32768 and up), so that no
            // connection another test opens meanwhile takes one of them as its local port.
            int offset = 100 * ThreadLocalRandom.current().nextInt(10, 225);
            if (allFree(offset)) {
                return offset;
            }
        }
        throw new IOException("no free block of ports found");
    }

    private static boolean allFree(int offset) {
        for (int b : DEFAULTS) {
            try (ServerSocket s = new ServerSocket()) {
                s.bind(new InetSocketAddress("127.0.0.1", b + offset));
            } catch (IOException e) {
                return false;
            }
        }
        return true;
    }
}
