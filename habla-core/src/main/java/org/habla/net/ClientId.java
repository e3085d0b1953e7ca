package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Who a control client is, as the daemon can tell it: its connection on one socket ({@code action#3}, the third
 * connection the socket accepted since it started) or the bridge it came through ({@code mqtt-bridge}), and the
 * address it came from. A JSON object on the wire, so
 * that a name the client proves later can join these fields without changing their meaning.
 *
 * @param connection the socket's name, {@code #} and the connection's number on that socket; or a bridge's name
 * @param address    the peer's {@code host:port} (for a bridge, its broker's)
 */
public record ClientId(String connection, String address) {

    public ObjectNode toJson() {
        return JsonNodeFactory.instance.objectNode().put("connection", connection).put("address", address);
    }

    @Override
    public String toString() {
        return connection + " (" + address + ")";
    }
}
