package org.habla.plugin;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;

/**
 * Makes drivers of one native protocol. Registered through
 * {@code META-INF/services/org.habla.plugin.DriverProvider}; a config's interface names it by {@link #name()}.
 *
 * @param <P> the params record the interface's {@code params} object is bound to
 */
public interface DriverProvider<P extends Record> {

    /** The stable type name used in configs, e.g. {@code "pioneer"}. */
    String name();

    /** One sentence on the protocol and the hardware it speaks to. */
    String description();

    /** The record the {@code params} object is bound to ({@link NoParams} for none). */
    Class<P> paramsType();

    /** A new driver for the robot at {@code address}. Cheap: no I/O. */
    Driver create(InterfaceAddress address, P params);
}
