package org.habla.daemon;

import java.io.IOException;
import java.util.Objects;
import java.util.Optional;
import org.habla.config.HablaConfig;
import org.habla.plugin.PluginRegistry;

/**
 * A product that runs beside a daemon and reads it — the live monitor — registered through
 * {@code META-INF/services/org.habla.daemon.DaemonExtension}, so the engine never names it. The daemon starts every
 * one it finds once its own ports are bound and before any of them is served, and closes them after its control
 * sockets and before its graph stops. An extension sees the daemon only as a {@link LiveGraph}: it cannot write to
 * the graph.
 */
public interface DaemonExtension {

    /**
     * Starts beside the daemon of {@code config}, or does nothing when the config does not ask for it.
     *
     * @throws PortsUnavailableException when a port of its own cannot be had, naming the port's JSON path; the daemon
     *                                   then stops what it started and does not start
     */
    Optional<Running> start(HablaConfig config, PluginRegistry registry, LiveGraph daemon) throws IOException;

    /**
     * A started extension.
     *
     * @param name    what {@link Daemon#extensionPort} knows it by ({@code "monitor"})
     * @param port    the port it listens on (0: none)
     * @param where   what the daemon's start line says of it ({@code "monitor on http://127.0.0.1:7098/"})
     * @param product stops it
     */
    record Running(String name, int port, String where, AutoCloseable product) {

        public Running {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(where, "where");
            Objects.requireNonNull(product, "product");
        }
    }
}
