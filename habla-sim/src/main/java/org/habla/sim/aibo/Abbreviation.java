package org.habla.sim.aibo;

/** Client text shortened and made printable for a log line. */
final class Abbreviation {

    private static final int MAX_CHARS = 60;

    private Abbreviation() {
    }

    static String of(String text) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < text.length() && b.length() < MAX_CHARS; i++) {
            char c = text.charAt(i);
            b.append(c < 0x20 || c == 0x7f ? String.format("\\x%02x", (int) c) : String.valueOf(c));
        }
        return text.length() > MAX_CHARS ? b + "…" : b.toString();
    }
}
