package org.habla.config;

import org.habla.driver.InterfaceAddress;

/**
 * One robot interface: a driver type, where the robot's servers are, and the driver's params.
 *
 * @param id        the id used in channel references ({@code "@id.channel"})
 * @param driver    the driver type name
 * @param address   host and optional main port
 * @param params    the driver's own params record, already validated
 * @param reconnect how the link is re-established
 */
public record InterfaceConfig(String id, String driver, InterfaceAddress address, Record params, Reconnect reconnect) {
}
