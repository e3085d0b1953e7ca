package org.habla.graph;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Lowers the calling thread's share of the processor on Linux by raising its nice value, which any user may do
 * to their own threads: Linux keeps a nice value per thread, and the calling thread's id is the last part of
 * {@code /proc/thread-self}. The value is set with the system's {@code renice}, once per thread. Where there is
 * no such file or command, nothing changes and one line says so.
 */
final class ThreadNice {

    private static final Logger LOG = LoggerFactory.getLogger(ThreadNice.class);
    private static final Path THREAD_SELF = Path.of("/proc/thread-self");
    private static volatile boolean warned;

    private ThreadNice() {
    }

    /** Sets the calling thread's nice value to {@code nice} (1 to 19); false, logged once, where it cannot. */
    static boolean lowerTo(int nice) {
        if (nice < 1 || nice > 19) {
            throw new IllegalArgumentException("a nice value to lower a thread to is 1 to 19, not " + nice);
        }
        OptionalInt tid = threadId();
        if (tid.isEmpty()) {
            return cannot("no " + THREAD_SELF);
        }
        try {
            Process p = new ProcessBuilder("renice", "-n", Integer.toString(nice), "-p", Integer.toString(tid.getAsInt()))
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return cannot("renice did not end within 10 s");
            }
            return p.exitValue() == 0 || cannot("renice exited with " + p.exitValue());
        } catch (IOException e) {
            return cannot(e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /**
     * A scheduling property's value: 0 when unset or blank, else a whole number from 0 to {@code max}.
     *
     * @throws IllegalArgumentException naming the property and what it {@code takes}, for anything else
     */
    static int property(String name, String value, int max, String takes) {
        if (value == null || value.isBlank()) {
            return 0;
        }
        try {
            int n = Integer.parseInt(value.strip());
            if (n >= 0 && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("-D" + name + " takes " + takes + ", not '" + value + "'");
    }

    /** The calling thread's nice value as Linux reports it, if it does. */
    static OptionalInt current() {
        OptionalInt tid = threadId();
        if (tid.isEmpty()) {
            return OptionalInt.empty();
        }
        try {
            String stat = Files.readString(Path.of("/proc/self/task/" + tid.getAsInt() + "/stat"));
            // Fields after the command name, which is in parentheses and may hold spaces: nice is field 19.
            String[] after = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return OptionalInt.of(Integer.parseInt(after[16]));
        } catch (IOException | RuntimeException e) {
            return OptionalInt.empty();
        }
    }

    /** The calling thread's id on Linux, the last part of {@code /proc/thread-self}. */
    static OptionalInt threadId() {
        try {
            String self = Files.readSymbolicLink(THREAD_SELF).toString(); // "PID/task/TID"
            return OptionalInt.of(Integer.parseInt(self.substring(self.lastIndexOf('/') + 1)));
        } catch (IOException | UnsupportedOperationException | NumberFormatException e) {
            return OptionalInt.empty();
        }
    }

    private static boolean cannot(String why) {
        if (!warned) {
            warned = true;
            LOG.warn("background threads keep the normal processor share: cannot set their nice value ({})", why);
        }
        return false;
    }
}
