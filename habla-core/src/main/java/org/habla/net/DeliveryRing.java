package org.habla.net;

import java.util.Collection;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * The order in which one socket hands a sample to its clients. Handing out is sequential (one outbox after
 * another, each waking that client's writer), so whoever comes first is written first; each sample therefore
 * starts one client further along the ring, and over any {@code n} samples each of {@code n} clients is first
 * once and last once, whatever its place in the connection order.
 *
 * <pre>
 *   sample 1:  c1 c2 c3 c4
 *   sample 2:  c2 c3 c4 c1
 *   sample 3:  c3 c4 c1 c2
 * </pre>
 */
final class DeliveryRing {

    private final AtomicInteger turn = new AtomicInteger();

    /** Calls {@code deliver} once for each of {@code clients} (a snapshot of them), starting one further each time. */
    <T> void forEach(Collection<T> clients, Consumer<? super T> deliver) {
        Object[] all = clients.toArray();
        int n = all.length;
        if (n == 0) {
            return;
        }
        int start = Math.floorMod(turn.getAndIncrement(), n);
        for (int i = 0; i < n; i++) {
            @SuppressWarnings("unchecked")
            T c = (T) all[(start + i) % n];
            deliver.accept(c);
        }
    }
}
