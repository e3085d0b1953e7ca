package org.habla.net;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The memory a set of connections may hold for {@code "bytes"} blocks still arriving, counted in bytes: one
 * budget per port, inside one for the whole process. A reader reserves room as a block's bytes come in and
 * releases it once the block is whole (or abandoned), so a header that declares 8 MiB and sends nothing
 * costs nothing, and a crowd of them cannot hold more than the budget.
 *
 * <pre>
 *   process budget (limits.processBlockBudgetBytes)
 *     +-- port 7004 budget (limits.socketBlockBudgetBytes) -- connection readers reserve / release
 *     +-- port 7002 budget (limits.socketBlockBudgetBytes) -- ...
 * </pre>
 *
 * Thread-safe. {@link #reserved()} is the daemon's own count of bytes held for blocks in flight.
 */
public final class BlockBudget {

    private final String name;
    private final long limitBytes;
    private final BlockBudget parent;
    private final AtomicLong reserved = new AtomicLong();

    private BlockBudget(String name, long limitBytes, BlockBudget parent) {
        this.name = Objects.requireNonNull(name, "name");
        if (limitBytes < 0) {
            throw new IllegalArgumentException("a block budget must not be negative, was " + limitBytes);
        }
        this.limitBytes = limitBytes;
        this.parent = parent;
    }

    /**
     * A top-level budget.
     *
     * @param name what the refusal names, e.g. {@code limits.processBlockBudgetBytes}
     */
    public static BlockBudget of(String name, long limitBytes) {
        return new BlockBudget(name, limitBytes, null);
    }

    /** A budget without a bound, for connections the daemon opens itself and for tests. */
    public static BlockBudget unbounded() {
        return new BlockBudget("unbounded", Long.MAX_VALUE, null);
    }

    /** A budget inside this one: a reservation must fit both. */
    public BlockBudget child(String name, long limitBytes) {
        return new BlockBudget(name, limitBytes, this);
    }

    /**
     * Reserves {@code bytes} here and in every enclosing budget, or nothing.
     *
     * @throws FrameException {@code block_budget} (recoverable), naming the budget that is full
     */
    public void reserve(long bytes) throws FrameException {
        BlockBudget full = tryReserve(bytes);
        if (full != null) {
            throw FrameException.recoverable("block_budget", "blocks in flight would exceed " + full.name + "="
                    + full.limitBytes + " bytes (" + full.reserved() + " held now); the block is discarded");
        }
    }

    /** Reserves {@code bytes} everywhere or nowhere; returns null, or the budget that had no room. */
    private BlockBudget tryReserve(long bytes) {
        long now = reserved.get();
        while (true) {
            if (bytes > limitBytes - now) {
                return this;
            }
            if (reserved.compareAndSet(now, now + bytes)) {
                break;
            }
            now = reserved.get();
        }
        if (parent != null) {
            BlockBudget full = parent.tryReserve(bytes);
            if (full != null) {
                reserved.addAndGet(-bytes);
                return full;
            }
        }
        return null;
    }

    /** Gives back {@code bytes} reserved earlier, here and in every enclosing budget. */
    public void release(long bytes) {
        reserved.addAndGet(-bytes);
        if (parent != null) {
            parent.release(bytes);
        }
    }

    /** Bytes held now for blocks in flight. */
    public long reserved() {
        return reserved.get();
    }

    public long limitBytes() {
        return limitBytes;
    }

    /** The limit's name, as refusals give it. */
    public String name() {
        return name;
    }
}
