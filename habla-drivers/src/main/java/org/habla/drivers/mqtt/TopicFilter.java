package org.habla.drivers.mqtt;

/**
 * An MQTT topic filter: levels separated by {@code /}, where {@code +} matches exactly one level and a final
 * {@code #} matches the rest (also nothing). {@code zigbee2mqtt/+/availability} matches
 * {@code zigbee2mqtt/kitchen_motion/availability}; {@code tele/#} matches {@code tele} and {@code tele/a/b}.
 */
record TopicFilter(String text) {

    /** The longest topic or filter MQTT allows, in UTF-8 bytes. */
    static final int MAX_BYTES = 65_535;

    TopicFilter {
        check(text, true);
    }

    /** Checks a topic to publish on: no wildcards. */
    static String topic(String text) {
        check(text, false);
        return text;
    }

    boolean matches(String topic) {
        String[] f = text.split("/", -1);
        String[] t = topic.split("/", -1);
        for (int i = 0; i < f.length; i++) {
            if (f[i].equals("#")) {
                return true;
            }
            if (i >= t.length) {
                return false;
            }
            if (!f[i].equals("+") && !f[i].equals(t[i])) {
                return false;
            }
        }
        return f.length == t.length;
    }

    private static void check(String text, boolean wildcards) {
        if (text == null || text.isEmpty()) {
            throw new IllegalArgumentException("a topic cannot be empty");
        }
        if (text.getBytes(java.nio.charset.StandardCharsets.UTF_8).length > MAX_BYTES || text.indexOf('\0') >= 0) {
            throw new IllegalArgumentException("topic '" + text + "' is too long or holds a NUL");
        }
        String[] levels = text.split("/", -1);
        for (int i = 0; i < levels.length; i++) {
            String level = levels[i];
            boolean wild = level.contains("+") || level.contains("#");
            if (wild && !wildcards) {
                throw new IllegalArgumentException("topic '" + text + "' holds a wildcard; a command goes to one topic");
            }
            if (wild && !(level.equals("+") || level.equals("#") && i == levels.length - 1)) {
                throw new IllegalArgumentException("topic filter '" + text
                        + "': '+' must stand alone in a level, '#' alone in the last level");
            }
        }
    }
}
