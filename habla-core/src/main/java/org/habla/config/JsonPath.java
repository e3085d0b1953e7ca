package org.habla.config;

import java.util.regex.Pattern;

/**
 * A position in a config file, written the way errors show it: {@code $.methods[3].inputs.ranges}.
 * Keys that are not plain names are quoted: {@code $.params["odd key"]}.
 */
record JsonPath(String text) {

    static final JsonPath ROOT = new JsonPath("$");

    private static final Pattern PLAIN = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$-]*");

    JsonPath field(String key) {
        if (PLAIN.matcher(key).matches()) {
            return new JsonPath(text + "." + key);
        }
        return new JsonPath(text + "[\"" + key.replace("\\", "\\\\").replace("\"", "\\\"") + "\"]");
    }

    JsonPath index(int i) {
        return new JsonPath(text + "[" + i + "]");
    }

    @Override
    public String toString() {
        return text;
    }
}
