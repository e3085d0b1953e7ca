package org.habla.config;

import org.habla.driver.InterfaceAddress;

/**
 * One bridge of a config: a bridge type, where it connects (a broker), and its params.
 *
 * @param id      the bridge's id, for logs and the status
 * @param type    the bridge type name
 * @param address host and optional port
 * @param params  the type's own params record, already validated
 */
public record BridgeConfig(String id, String type, InterfaceAddress address, Record params) {
}
