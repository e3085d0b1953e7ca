package org.habla.net;

/**
 * When a served connection last did something, as its {@link ConnectionGuard} reads it: sent a whole frame,
 * or took bytes we wrote. Written by the connection's reader and writer threads, read by the guard's sweeper.
 */
public final class PeerActivity {

    private final long connectedNanos = System.nanoTime();
    private volatile long lastActiveNanos = connectedNanos;

    /** The peer sent a whole, well-formed frame. */
    public void received() {
        lastActiveNanos = System.nanoTime();
    }

    /** The peer's TCP stack took bytes we wrote. */
    public void delivered() {
        lastActiveNanos = System.nanoTime();
    }

    public long connectedNanos() {
        return connectedNanos;
    }

    /** When it last did either; when it connected before. */
    public long lastActiveNanos() {
        return lastActiveNanos;
    }
}
