package org.habla.drivers.pioneer;

import java.util.HexFormat;

/** Hex text to bytes and back, for tests written from the reference's byte tables. */
final class Hex {

    private Hex() {
    }

    /** {@code "FA FB 03"} → bytes. */
    static byte[] bytes(String spaced) {
        return HexFormat.of().parseHex(spaced.replace(" ", ""));
    }

    static String text(byte[] bytes) {
        return HexFormat.ofDelimiter(" ").withUpperCase().formatHex(bytes);
    }
}
