package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Who a control client is, as the daemon can tell it: the name it proved ({@code mdb}, or {@code anonymous} where
 * a port needs no authentication), its connection on one socket ({@code action#3}, the third connection the socket
 * accepted since it started) or the bridge it came through ({@code mqtt-bridge}), and the address it came from.
 *
 * @param client     the authenticated client's name, or {@code anonymous}
 * @param connection the socket's name, {@code #} and the connection's number on that socket; or a bridge's name
 * @param address    the peer's {@code host:port} (for a bridge, its broker's)
 */
public record ClientId(String client, String connection, String address) {

    /** How a client that did not authenticate is named. */
    public static final String ANONYMOUS = "anonymous";

    /** An anonymous client. */
    public ClientId(String connection, String address) {
        this(ANONYMOUS, connection, address);
    }

    /** The same connection, known now as {@code name}. */
    public ClientId named(String name) {
        return new ClientId(name, connection, address);
    }

    /** The host part of {@link #address}: the address without its port. */
    public String host() {
        int colon = address.lastIndexOf(':');
        return colon < 0 ? address : address.substring(0, colon);
    }

    public ObjectNode toJson() {
        return JsonNodeFactory.instance.objectNode().put("client", client).put("connection", connection)
                .put("address", address);
    }

    @Override
    public String toString() {
        return ANONYMOUS.equals(client) ? connection + " (" + address + ")"
                : client + " (" + connection + ", " + address + ")";
    }
}
