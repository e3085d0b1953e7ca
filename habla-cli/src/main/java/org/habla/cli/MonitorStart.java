package org.habla.cli;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import org.habla.config.ConfigError;
import org.habla.config.HablaConfig;
import org.habla.config.StatusConfig;
import org.habla.daemon.Daemon;
import org.habla.daemon.DaemonExtension;
import org.habla.daemon.LiveGraph;
import org.habla.daemon.PortsUnavailableException;
import org.habla.draw.GraphPicture;
import org.habla.draw.SvgWriter;
import org.habla.monitor.Monitor;
import org.habla.plugin.PluginRegistry;

/**
 * Starts the live monitor beside a daemon whose config gives it a port ({@code status.monitorPort}), showing the
 * picture {@code habla graph --format svg} draws of the config. The monitor draws nothing itself; the command line
 * assembles the two.
 */
public final class MonitorStart implements DaemonExtension {

    @Override
    public Optional<Running> start(HablaConfig config, PluginRegistry registry, LiveGraph daemon) throws IOException {
        StatusConfig status = config.status();
        if (status.monitorPort() <= 0) {
            return Optional.empty();
        }
        Monitor monitor;
        try {
            monitor = Monitor.start(status.monitorBind(), status.monitorPort(), daemon,
                    () -> SvgWriter.write(GraphPicture.of(config, registry)));
        } catch (IOException e) {
            throw new PortsUnavailableException(List.of(new ConfigError("$.status.monitorPort", e.getMessage())));
        }
        return Optional.of(new Running(Daemon.MONITOR, monitor.port(),
                "monitor on http://" + status.monitorBind() + ":" + monitor.port() + "/", monitor));
    }
}
