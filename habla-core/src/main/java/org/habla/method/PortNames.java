package org.habla.method;

import java.util.regex.Pattern;

/** The rule for input and output names: a letter, then letters, digits, '_' or '-'. */
final class PortNames {

    private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,63}");

    private PortNames() {
    }

    static String check(String name) {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("port name '" + name
                    + "' must be a letter then up to 63 letters, digits, '_' or '-'");
        }
        return name;
    }
}
