package org.habla.bridge;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.List;
import org.habla.net.ControlPoint;

/**
 * Carries exposed methods to another transport, beside their control sockets: it sees the same
 * {@link ControlPoint}s a control server sees, so it streams the same samples and staleness and writes actions
 * through the same checks. A bridge never blocks the engine: it hands samples on or drops them, counted. Its
 * connection is kept by the engine, as every link's is ({@link BridgeSession}).
 *
 * <pre>
 *   graph ──samples──▶ ControlPoint ──▶ ControlServer (TCP port, one per method)
 *                                  └──▶ Bridge        (e.g. MQTT topics, all methods over one connection)
 *   Bridge ──write, if its CommandRole allows the socket──▶ ControlPoint ──▶ the method's control input
 * </pre>
 */
public interface Bridge extends AutoCloseable {

    /**
     * Attaches to the daemon's exposed methods; opens no connection (the engine then keeps one up through
     * {@link #session()}). What reaches the bridge while no session is up is dropped and counted. An
     * {@link IOException} stops the daemon's start.
     *
     * @param system the config's system name
     * @param points every exposed method, in config order
     * @param role   which sockets the bridge may write actions to
     */
    void start(String system, List<ControlPoint> points, CommandRole role) throws IOException;

    /** A fresh session for each connection the engine opens, after {@link #start}. */
    BridgeSession session();

    /**
     * The bridge's own figures for the status endpoint (samples carried and dropped, actions taken and refused);
     * the engine adds its link's ({@code connected}, {@code connects}, {@code failures}, {@code lastError}).
     */
    ObjectNode status();

    /** Stops carrying, after the engine has closed its session. Safe to call twice. */
    @Override
    void close();
}
