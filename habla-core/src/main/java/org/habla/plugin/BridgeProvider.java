package org.habla.plugin;

import java.util.Set;
import org.habla.bridge.Bridge;
import org.habla.driver.InterfaceAddress;

/**
 * Makes bridges of one kind. Registered through {@code META-INF/services/org.habla.plugin.BridgeProvider}; a
 * config's {@code bridges} entry names it by {@link #name()}.
 *
 * @param <P> the params record the entry's {@code params} object is bound to
 */
public interface BridgeProvider<P extends Record> {

    /** The stable type name used in configs, e.g. {@code "mqtt"}. */
    String name();

    /** One sentence on what the bridge carries and where to. */
    String description();

    Class<P> paramsType();

    /** The sockets the params name, so the config check can say which of them no method exposes. */
    Set<String> socketsNamed(P params);

    /** The sockets the params let the bridge write actions to (its command role). */
    Set<String> actionSockets(P params);

    /** A new bridge to {@code address}. Cheap: no I/O. */
    Bridge create(InterfaceAddress address, P params);
}
