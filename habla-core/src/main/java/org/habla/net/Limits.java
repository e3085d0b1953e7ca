package org.habla.net;

/**
 * The limits every socket the daemon serves enforces; each is named in the error a client gets when it
 * crosses it. See {@code docs/config.md} and, for the admission and eviction policy, {@code docs/protocol.md}.
 *
 * @param maxLineBytes            the longest JSON line accepted, newline excluded
 * @param maxBinaryBytes          the largest {@code "bytes"} block accepted after a line
 * @param maxClientsPerPort       clients (connections admitted: a first request or, where the port requires it, an
 *                                authentication) at once on one port; at the cap a new client evicts one idle for
 *                                {@code evictableIdleMs}, or is refused
 * @param clientQueueSamples      samples waiting for one slow client before the oldest are dropped (and counted)
 * @param maxPendingPerPort       connections at once on one port not admitted yet; of the address with the most of
 *                                them, the one waiting longest gives way to a newcomer
 * @param idleTimeoutMs           a connection that has taken nothing of the lines waiting for it and sent nothing for
 *                                this long, or has not authenticated within it, is closed ({@code idle_timeout}); a
 *                                reader that takes what it is sent is never idle; 0 never closes an idle connection
 * @param frameTimeoutMs          a frame a peer has begun to send must arrive whole within this long
 *                                ({@code frame_timeout}); the status endpoint's answer must be taken within it
 * @param evictableIdleMs         on a full port, a client that has sent requests but then neither sent nor taken
 *                                anything for this long may be evicted to admit a newcomer
 * @param socketBlockBudgetBytes  the bytes of {@code "bytes"} blocks in flight on one port, all its connections
 *                                together ({@code block_budget})
 * @param processBlockBudgetBytes the bytes of blocks in flight on every port of the process together
 */
public record Limits(int maxLineBytes, int maxBinaryBytes, int maxClientsPerPort, int clientQueueSamples,
        int maxPendingPerPort, long idleTimeoutMs, long frameTimeoutMs, long evictableIdleMs, long socketBlockBudgetBytes,
        long processBlockBudgetBytes) {

    /** Default of {@link #maxClientsPerPort}. */
    public static final int CLIENTS_PER_PORT = 16;
    /** Default of {@link #maxPendingPerPort}: a burst of this many silent connections cannot push out a newcomer. */
    public static final int PENDING_PER_PORT = 256;
    /** Default of {@link #idleTimeoutMs}: five minutes. */
    public static final long IDLE_TIMEOUT_MS = 300_000;
    /** Default of {@link #frameTimeoutMs}: ten seconds, an 8 MiB block at 1 MB/s with room to spare. */
    public static final long FRAME_TIMEOUT_MS = 10_000;
    /**
     * Default of {@link #evictableIdleMs}: two minutes, so that a client of a quiet socket that pings every minute, as
     * the control contract asks, is never the one to give way.
     */
    public static final long EVICTABLE_IDLE_MS = 120_000;
    /** Default of {@link #socketBlockBudgetBytes}: two blocks of the default largest size. */
    public static final long SOCKET_BLOCK_BUDGET_BYTES = 16L * 1024 * 1024;
    /** Default of {@link #processBlockBudgetBytes}. */
    public static final long PROCESS_BLOCK_BUDGET_BYTES = 64L * 1024 * 1024;

    public static final Limits DEFAULTS = new Limits(65_536, 8 * 1024 * 1024, CLIENTS_PER_PORT, 256);

    /**
     * The four framing and queue limits with the defaults for the deadlines; the block budgets are at least
     * their defaults and never below one largest block.
     */
    public Limits(int maxLineBytes, int maxBinaryBytes, int maxClientsPerPort, int clientQueueSamples) {
        this(maxLineBytes, maxBinaryBytes, maxClientsPerPort, clientQueueSamples, PENDING_PER_PORT, IDLE_TIMEOUT_MS,
                FRAME_TIMEOUT_MS, EVICTABLE_IDLE_MS, Math.max(SOCKET_BLOCK_BUDGET_BYTES, maxBinaryBytes),
                Math.max(PROCESS_BLOCK_BUDGET_BYTES, maxBinaryBytes));
    }

    /** These limits with other deadlines (tests and benchmarks shorten them). */
    public Limits withDeadlines(long idleTimeoutMs, long frameTimeoutMs, long evictableIdleMs) {
        return new Limits(maxLineBytes, maxBinaryBytes, maxClientsPerPort, clientQueueSamples, maxPendingPerPort,
                idleTimeoutMs,
                frameTimeoutMs, evictableIdleMs, socketBlockBudgetBytes, processBlockBudgetBytes);
    }

    /** These limits with other caps on connections. */
    public Limits withCaps(int maxClientsPerPort, int maxPendingPerPort) {
        return new Limits(maxLineBytes, maxBinaryBytes, maxClientsPerPort, clientQueueSamples, maxPendingPerPort,
                idleTimeoutMs, frameTimeoutMs, evictableIdleMs, socketBlockBudgetBytes, processBlockBudgetBytes);
    }

    /** These limits with other block budgets. */
    public Limits withBlockBudgets(long socketBlockBudgetBytes, long processBlockBudgetBytes) {
        return new Limits(maxLineBytes, maxBinaryBytes, maxClientsPerPort, clientQueueSamples, maxPendingPerPort,
                idleTimeoutMs,
                frameTimeoutMs, evictableIdleMs, socketBlockBudgetBytes, processBlockBudgetBytes);
    }
}
