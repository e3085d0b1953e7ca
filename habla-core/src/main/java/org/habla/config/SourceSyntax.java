package org.habla.config;

import java.util.regex.Pattern;

/**
 * The text forms of the config's references: input sources ({@code "methodId.output"},
 * {@code "@interfaceId.channel"}, {@code "control"}), command targets ({@code "@interfaceId.channel"})
 * and ids.
 */
final class SourceSyntax {

    /** Ids of methods and interfaces, names of sockets: a letter, then up to 63 letters, digits, '_' or '-'. */
    static final Pattern ID = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,63}");

    static final String ID_RULE = "a letter then up to 63 letters, digits, '_' or '-'";

    private static final String SOURCE_FORMS =
            "write \"methodId.output\", \"@interfaceId.channel\" or \"control\"";

    private SourceSyntax() {
    }

    /** Parses an input source; throws {@link IllegalArgumentException} naming the accepted forms. */
    static Source source(String text) {
        if (text.equals("control")) {
            return new Source.Control();
        }
        if (text.startsWith("@")) {
            ChannelRef ref = channel(text, SOURCE_FORMS);
            return new Source.Channel(ref.interfaceId(), ref.channel());
        }
        String[] parts = pair(text, SOURCE_FORMS);
        return new Source.MethodOutput(parts[0], parts[1]);
    }

    /** Parses a command target {@code "@interfaceId.channel"}. */
    static ChannelRef commandTarget(String text) {
        return channel(text, "write \"@interfaceId.channel\"");
    }

    private static ChannelRef channel(String text, String forms) {
        if (!text.startsWith("@")) {
            throw new IllegalArgumentException("'" + text + "' is not a channel reference: " + forms);
        }
        String[] parts = pair(text.substring(1), forms);
        return new ChannelRef(parts[0], parts[1]);
    }

    private static String[] pair(String text, String forms) {
        int dot = text.indexOf('.');
        if (dot < 0) {
            throw new IllegalArgumentException("'" + text + "' has no '.': " + forms);
        }
        String left = text.substring(0, dot);
        String right = text.substring(dot + 1);
        if (!ID.matcher(left).matches() || !ID.matcher(right).matches()) {
            throw new IllegalArgumentException("'" + text + "' is not a reference: " + forms
                    + ", each name " + ID_RULE);
        }
        return new String[] {left, right};
    }
}
