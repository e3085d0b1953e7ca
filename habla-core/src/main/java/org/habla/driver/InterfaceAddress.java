package org.habla.driver;

import java.util.Objects;
import java.util.OptionalInt;

/**
 * Where a robot's interface servers are: a host, and optionally the port of the driver's main server
 * (drivers that talk to several servers take their other ports from their params).
 */
public record InterfaceAddress(String host, OptionalInt port) {

    public InterfaceAddress {
        Objects.requireNonNull(host, "host");
        if (host.isBlank()) {
            throw new IllegalArgumentException("host is empty");
        }
        if (port.isPresent() && (port.getAsInt() < 1 || port.getAsInt() > 65_535)) {
            throw new IllegalArgumentException("port must be in 1..65535, was " + port.getAsInt());
        }
    }

    /** Parses {@code "host"}, {@code "host:port"} or {@code "[v6]:port"}. */
    public static InterfaceAddress parse(String text) {
        Objects.requireNonNull(text, "address");
        String host = text;
        OptionalInt port = OptionalInt.empty();
        int colon = text.lastIndexOf(':');
        boolean bracketed = text.startsWith("[");
        if (colon > 0 && (bracketed ? text.indexOf(']') < colon : text.indexOf(':') == colon)) {
            host = text.substring(0, colon);
            String p = text.substring(colon + 1);
            try {
                port = OptionalInt.of(Integer.parseInt(p));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("port '" + p + "' is not a number");
            }
        }
        if (bracketed) {
            host = host.replace("[", "").replace("]", "");
        }
        return new InterfaceAddress(host, port);
    }

    /** The port, or {@code defaultPort} if the address names none. */
    public int portOr(int defaultPort) {
        return port.orElse(defaultPort);
    }

    @Override
    public String toString() {
        return port.isPresent() ? host + ":" + port.getAsInt() : host;
    }
}
