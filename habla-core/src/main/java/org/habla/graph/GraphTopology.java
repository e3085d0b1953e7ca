package org.habla.graph;

import java.util.LinkedHashSet;
import java.util.Set;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Source;

/**
 * Who feeds whom in a config's method graph, read from the config alone: the interfaces and channels upstream of a
 * method, the methods downstream of it or feeding it. The engine asks it once while wiring (staleness, the motion
 * path, which sockets hear a method's notices) and a replay asks it where an event can reach.
 */
final class GraphTopology {

    private final HablaConfig config;

    GraphTopology(HablaConfig config) {
        this.config = config;
    }

    /** The interfaces whose readings reach {@code methodId}. */
    Set<String> upstreamInterfaces(String methodId) {
        Set<String> result = new LinkedHashSet<>();
        upstreamChannels(methodId).forEach(ch -> result.add(ch.interfaceId()));
        return result;
    }

    /** The interface channels whose readings reach {@code methodId}. */
    Set<Source.Channel> upstreamChannels(String methodId) {
        Set<Source.Channel> result = new LinkedHashSet<>();
        upstreamChannels(methodId, new LinkedHashSet<>(), result);
        return result;
    }

    private void upstreamChannels(String methodId, Set<String> visited, Set<Source.Channel> result) {
        if (!visited.add(methodId)) {
            return;
        }
        for (Source s : config.method(methodId).orElseThrow().inputs().values()) {
            switch (s) {
                case Source.Channel ch -> result.add(ch);
                case Source.MethodOutput mo -> upstreamChannels(mo.methodId(), visited, result);
                case Source.Control c -> { }
            }
        }
    }

    /** The method and every method whose outputs feed it, directly or not. */
    Set<String> feeding(String methodId) {
        Set<String> found = new LinkedHashSet<>();
        feeding(methodId, found);
        return found;
    }

    /** Adds the method and every method whose outputs feed it to {@code found}. */
    void feeding(String methodId, Set<String> found) {
        if (!found.add(methodId)) {
            return;
        }
        for (Source s : config.method(methodId).orElseThrow().inputs().values()) {
            if (s instanceof Source.MethodOutput mo) {
                feeding(mo.methodId(), found);
            }
        }
    }

    /** The method and every method its outputs feed, directly or not. */
    Set<String> downstream(String methodId) {
        Set<String> found = new LinkedHashSet<>();
        downstream(methodId, found);
        return found;
    }

    private void downstream(String methodId, Set<String> found) {
        if (!found.add(methodId)) {
            return;
        }
        for (MethodConfig mc : config.methods()) {
            for (Source s : mc.inputs().values()) {
                if (s instanceof Source.MethodOutput mo && mo.methodId().equals(methodId)) {
                    downstream(mc.id(), found);
                }
            }
        }
    }

    /** Whether the method, or one its outputs feed, writes an interface's command channel. */
    boolean actuates(String methodId) {
        return downstream(methodId).stream().anyMatch(id -> !config.method(id).orElseThrow().commands().isEmpty());
    }
}
