package org.habla.sim;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.ThreadLocalRandom;

/**
 * A port offset for tests that run a whole robot set-up: every port the simulators, the daemon and its
 * sockets use (their defaults plus the offset) is free when it is chosen, and no other test JVM on this machine
 * holds an offset whose ports could meet these. Test JVMs run side by side, and a block's ports are bound only
 * later, by the processes the test starts: so each JVM holds a lock file per offset it has handed out (its last
 * {@link #HELD_PER_JVM}), and an offset within {@link #SPAN} of one another JVM holds is not chosen. Each JVM
 * locks its offset first and looks at the others after, so of two that choose at once, at least one sees the other.
 */
public final class PortBlock {

    private static final int[] DEFAULTS = {7001, 7002, 7003, 7004, 7010, 7011, 7012, 7013, 7098, 7099, 7600, 8101, 8110, 8120,
        8111, 8199, 10011, 10020, 10031, 10050, 10052, 10053, 10070, 10071, 10199};
    /** Two offsets closer than this may give the same port to two set-ups: the spread of {@link #DEFAULTS}. */
    static final int SPAN = 10199 - 7001 + 1;
    /** How many offsets one JVM holds at once: a test may run two set-ups side by side. */
    static final int HELD_PER_JVM = 2;
    private static final String PREFIX = "habla-port-block-";
    private static final Deque<Held> HELD = new ArrayDeque<>();

    private record Held(int offset, FileChannel channel, FileLock lock) {
        void release() {
            try {
                channel.close(); // lets the lock go too
            } catch (IOException e) {
                // the file stays; the next JVM to look finds it unlocked, which is free
            }
        }
    }

    private PortBlock() {
    }

    public static synchronized int freeOffset() throws IOException {
        for (int attempt = 0; attempt < 200; attempt++) {
            // Every port of the block below the kernel's usual ephemeral range (32768 and up), so that no
            // connection another test opens meanwhile takes one of them as its local port.
            int offset = 100 * ThreadLocalRandom.current().nextInt(10, 225);
            Held held = lock(offset);
            if (held == null) {
                continue;
            }
            if (!heldElsewhereNear(offset) && allFree(offset)) {
                HELD.addLast(held);
                while (HELD.size() > HELD_PER_JVM) {
                    HELD.removeFirst().release();
                }
                return offset;
            }
            held.release();
        }
        throw new IOException("no free block of ports found");
    }

    private static Path dir() {
        return Path.of(System.getProperty("java.io.tmpdir"));
    }

    /** This JVM's lock on {@code offset}'s file, or null when another JVM (or this one) holds it. */
    private static Held lock(int offset) throws IOException {
        FileChannel channel = FileChannel.open(dir().resolve(PREFIX + offset), StandardOpenOption.CREATE,
                StandardOpenOption.WRITE);
        try {
            FileLock lock = channel.tryLock();
            if (lock != null) {
                return new Held(offset, channel, lock);
            }
        } catch (OverlappingFileLockException e) {
            // this JVM holds it already
        }
        channel.close();
        return null;
    }

    /** Whether another JVM holds an offset within {@link #SPAN} of {@code offset}. */
    private static boolean heldElsewhereNear(int offset) throws IOException {
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir(), PREFIX + "*")) {
            for (Path f : files) {
                int other;
                try {
                    other = Integer.parseInt(f.getFileName().toString().substring(PREFIX.length()));
                } catch (NumberFormatException e) {
                    continue;
                }
                if (other == offset || Math.abs(other - offset) >= SPAN || heldHere(other)) {
                    continue;
                }
                Held probe = lock(other);
                if (probe == null) {
                    return true; // locked by another JVM
                }
                probe.release();
            }
        }
        return false;
    }

    private static boolean heldHere(int offset) {
        return HELD.stream().anyMatch(h -> h.offset() == offset);
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
