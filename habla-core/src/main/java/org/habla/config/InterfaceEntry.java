package org.habla.config;

import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;

/**
 * One element of the config's {@code interfaces} array as far as it could be read. A null component
 * means that part was missing or wrong, and the error is already recorded.
 *
 * @param path      where the entry is ({@code $.interfaces[0]})
 * @param id        the id, or null
 * @param driver    the driver type, or null when unknown
 * @param address   the address, or null
 * @param params    the bound params record, or null
 * @param reconnect the reconnect settings (defaults where absent)
 * @param made      the driver made by its provider to read its channels, or null
 */
record InterfaceEntry(JsonPath path, String id, String driver, InterfaceAddress address, Record params,
        Reconnect reconnect, Driver made) {

    boolean complete() {
        return id != null && driver != null && address != null && params != null && made != null;
    }

    /** Every channel, the engine's {@code link} channel included; empty if the driver could not be made. */
    List<ChannelDescriptor> channels() {
        if (made == null) {
            return List.of();
        }
        return Stream.concat(made.channels().stream(), Stream.of(Driver.LINK_CHANNEL)).toList();
    }

    Optional<ChannelDescriptor> channel(String name) {
        return channels().stream().filter(c -> c.name().equals(name)).findFirst();
    }

    InterfaceConfig toConfig() {
        return new InterfaceConfig(id, driver, address, params, reconnect);
    }
}
