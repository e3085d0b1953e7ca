package org.habla.config;

import org.habla.driver.InterfaceAddress;

/**
 * One bridge of a config: a bridge type, where it connects (a broker), its params, and how its connection comes
 * back when lost.
 *
 * @param id        the bridge's id, for logs and the status
 * @param type      the bridge type name
 * @param address   host and optional port
 * @param params    the type's own params record, already validated
 * @param reconnect the back-off between connection attempts and the connect time-out, as an interface's
 */
public record BridgeConfig(String id, String type, InterfaceAddress address, Record params, Reconnect reconnect) {
}
