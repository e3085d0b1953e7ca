package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

class DeliveryRingTest {

    private static List<String> order(DeliveryRing ring, List<String> clients) {
        List<String> visited = new ArrayList<>();
        ring.forEach(clients, visited::add);
        return visited;
    }

    @Test
    void overAsManySamplesAsClientsEachClientIsFirstOnceAndLastOnce() {
        DeliveryRing ring = new DeliveryRing();
        List<String> clients = List.of("c1", "c2", "c3", "c4", "c5");
        Set<String> firsts = new HashSet<>();
        Set<String> lasts = new HashSet<>();
        for (int sample = 0; sample < clients.size(); sample++) {
            List<String> visited = order(ring, clients);
            firsts.add(visited.getFirst());
            lasts.add(visited.getLast());
        }
        assertThat(firsts).containsExactlyInAnyOrderElementsOf(clients);
        assertThat(lasts).containsExactlyInAnyOrderElementsOf(clients);
    }

    @Test
    void everyClientGetsEverySampleExactlyOnce() {
        DeliveryRing ring = new DeliveryRing();
        List<String> clients = List.of("c1", "c2", "c3");
        Map<String, Integer> got = new HashMap<>();
        for (int sample = 0; sample < 7; sample++) {
            ring.forEach(clients, c -> got.merge(c, 1, Integer::sum));
        }
        assertThat(got).containsOnlyKeys(clients).allSatisfy((c, n) -> assertThat(n).isEqualTo(7));
    }

    @Test
    void aClientThatJoinsOrLeavesChangesOnlyWhoIsVisitedFromTheNextSample() {
        DeliveryRing ring = new DeliveryRing();
        List<String> clients = new CopyOnWriteArrayList<>(List.of("c1", "c2"));
        assertThat(order(ring, clients)).containsExactlyInAnyOrder("c1", "c2");
        clients.add("c3");
        assertThat(order(ring, clients)).containsExactlyInAnyOrder("c1", "c2", "c3");
        clients.remove("c1");
        assertThat(order(ring, clients)).containsExactlyInAnyOrder("c2", "c3");
        assertThat(order(ring, List.of())).isEmpty();
    }
}
