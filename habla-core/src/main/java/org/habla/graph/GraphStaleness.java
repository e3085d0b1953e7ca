package org.habla.graph;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.habla.config.Source;

/**
 * Which methods' outputs are stale: a method is stale while an interface upstream of it is down, the device
 * behind an upstream channel is unavailable, or a worker upstream is lost without a local fallback. It is brought
 * up to date under the link-state lock, as part of the change that caused it, and tells each exposed method's
 * clients when its staleness changes.
 */
final class GraphStaleness {

    private final Map<String, MethodRunner> runners;
    private final Map<String, InterfaceLink> links;
    private final Map<String, RemotePlacement> placements;
    private final List<ExposedMethod> exposed;
    private final Map<String, Set<String>> upstreamInterfaces = new HashMap<>();
    private final Map<String, Set<Source.Channel>> upstreamChannels = new HashMap<>();
    private final Map<String, Set<String>> upstreamPlacements = new HashMap<>();

    GraphStaleness(GraphTopology topology, Map<String, MethodRunner> runners, Map<String, InterfaceLink> links,
            Map<String, RemotePlacement> placements, List<ExposedMethod> exposed) {
        this.runners = runners;
        this.links = links;
        this.placements = placements;
        this.exposed = exposed;
        for (String id : runners.keySet()) {
            upstreamInterfaces.put(id, topology.upstreamInterfaces(id));
            upstreamChannels.put(id, topology.upstreamChannels(id));
            Set<String> placedUpstream = new LinkedHashSet<>(topology.feeding(id));
            placedUpstream.retainAll(placements.keySet());
            upstreamPlacements.put(id, placedUpstream);
        }
    }

    /** Marks every method as it stands before anything runs: what depends on a link is stale until it is up. */
    void markAll() {
        for (MethodRunner r : runners.values()) {
            r.stale(cause(r.id()));
        }
    }

    /**
     * Marks stale every method that depends on something down or lost, and fresh again the others, telling the
     * clients of each exposed method whose staleness changed. Runs under the link-state lock.
     */
    void refresh() {
        for (MethodRunner r : runners.values()) {
            StaleCause cause = cause(r.id());
            boolean stale = cause != null;
            boolean changed = r.stale() != stale;
            r.stale(cause); // the cause may change while the method stays stale: the status tells the newest
            if (changed) {
                for (ExposedMethod x : exposed) {
                    if (x.methodId().equals(r.id())) {
                        x.staleChanged(stale, stale ? cause.why() : "all links up");
                    }
                }
            }
        }
    }

    /** Why a method's outputs are stale now, or null. */
    private StaleCause cause(String methodId) {
        for (String id : upstreamInterfaces.getOrDefault(methodId, Set.of())) {
            if (!links.get(id).up()) {
                return new StaleCause("@" + id, "interface " + id + " is down");
            }
        }
        for (Source.Channel ch : upstreamChannels.getOrDefault(methodId, Set.of())) {
            String why = links.get(ch.interfaceId()).unavailable(ch.channel());
            if (why != null) {
                String channel = "@" + ch.interfaceId() + "." + ch.channel();
                return new StaleCause(channel, "the device of " + channel + " is unavailable: " + why);
            }
        }
        for (String id : upstreamPlacements.getOrDefault(methodId, Set.of())) {
            RemotePlacement p = placements.get(id);
            if (!p.healthy()) {
                return new StaleCause(id, "worker " + p.host() + " of method " + id + " is lost");
            }
        }
        return null;
    }
}
