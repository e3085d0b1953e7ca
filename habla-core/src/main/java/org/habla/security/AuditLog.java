package org.habla.security;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The append-only audit log: one JSON line per accepted or refused command and per refused authentication
 * ({@link AuditEntry}), written through to the operating system as it happens. The file is only ever appended to
 * (opened with {@code O_APPEND}, created readable by its owner only); rotating it is the system's business
 * ({@code logrotate} with {@code copytruncate}). A line that cannot be written is counted and logged, and never
 * stops a command or the daemon. Listeners (a recording) see every entry too. Thread-safe.
 */
public final class AuditLog implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(AuditLog.class);

    private final Path file;
    private final FileChannel channel;
    private final List<Consumer<AuditEntry>> listeners = new CopyOnWriteArrayList<>();
    private final AtomicLong written = new AtomicLong();
    private final AtomicLong failed = new AtomicLong();

    private AuditLog(Path file, FileChannel channel) {
        this.file = file;
        this.channel = channel;
    }

    /** A log without a file: entries reach its listeners only. */
    public static AuditLog withoutFile() {
        return new AuditLog(null, null);
    }

    /** Opens (or creates, mode 600) {@code file} for appending. */
    public static AuditLog open(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!Files.exists(file)) {
            try {
                Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
            } catch (UnsupportedOperationException e) {
                Files.createFile(file);
            } catch (java.nio.file.FileAlreadyExistsException e) {
                // created meanwhile: append to it
            }
        }
        try {
            return new AuditLog(file, FileChannel.open(file, StandardOpenOption.WRITE, StandardOpenOption.APPEND));
        } catch (IOException e) {
            throw new IOException("cannot open the audit log " + file + ": " + e.getMessage(), e);
        }
    }

    /** Also hands every entry to {@code listener} (which must not block). */
    public void addListener(Consumer<AuditEntry> listener) {
        listeners.add(listener);
    }

    /** Appends one entry. */
    public void add(AuditEntry entry) {
        for (Consumer<AuditEntry> l : listeners) {
            try {
                l.accept(entry);
            } catch (RuntimeException e) {
                LOG.warn("an audit listener failed", e);
            }
        }
        if (channel == null) {
            return;
        }
        byte[] line = (entry.json().toString() + "\n").getBytes(UTF_8);
        synchronized (this) {
            try {
                ByteBuffer b = ByteBuffer.wrap(line);
                while (b.hasRemaining()) {
                    channel.write(b);
                }
                written.incrementAndGet();
            } catch (IOException e) {
                long n = failed.incrementAndGet();
                if (n == 1 || n % 1_000 == 0) {
                    LOG.error("audit log {}: cannot append ({} entries lost so far): {}", file, n, e.toString());
                }
            }
        }
    }

    /** The file, or null for a log without one. */
    public Path file() {
        return file;
    }

    public long written() {
        return written.get();
    }

    /** Entries that could not be appended. */
    public long failed() {
        return failed.get();
    }

    @Override
    public synchronized void close() {
        if (channel != null) {
            try {
                channel.close();
            } catch (IOException e) {
                LOG.debug("closing the audit log: {}", e.toString());
            }
        }
    }
}
