package org.habla.bridge;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.List;
import org.habla.net.ControlPoint;

/**
 * Carries exposed methods to another transport, beside their control sockets: it sees the same
 * {@link ControlPoint}s a control server sees, so it streams the same samples and staleness and writes actions
 * through the same checks. A bridge never blocks the engine: it hands samples on or drops them, counted.
 *
 * <pre>
 *   graph ──samples──▶ ControlPoint ──▶ ControlServer (TCP port, one per method)
 *                                  └──▶ Bridge        (e.g. MQTT topics, all methods over one connection)
 *   Bridge ──write, if its CommandRole allows the socket──▶ ControlPoint ──▶ the method's control input
 * </pre>
 */
public interface Bridge extends AutoCloseable {

    /**
     * Attaches to the daemon's exposed methods and starts carrying them; returns at once (a broker that is not
     * there yet is retried in the background). An {@link IOException} stops the daemon's start.
     *
     * @param system the config's system name
     * @param points every exposed method, in config order
     * @param role   which sockets the bridge may write actions to
     */
    void start(String system, List<ControlPoint> points, CommandRole role) throws IOException;

    /** Figures for the status endpoint: connected, samples carried and dropped, actions taken and refused. */
    ObjectNode status();

    /** Stops carrying and says goodbye. Safe to call twice. */
    @Override
    void close();
}
