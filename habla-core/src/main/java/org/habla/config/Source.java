package org.habla.config;

/**
 * Where an input of a method gets its samples, as written in the config's {@code inputs} object:
 * <ul>
 *   <li>{@code "methodId.output"}: an output of another method;</li>
 *   <li>{@code "@interfaceId.channel"}: a reading channel of an interface (sensors &amp; actuators layer only);</li>
 *   <li>{@code "control"}: values written by control clients on the method's socket (virtual layer only).</li>
 * </ul>
 */
public sealed interface Source {

    /** The text form used in configs. */
    String text();

    record MethodOutput(String methodId, String output) implements Source {
        @Override
        public String text() {
            return methodId + "." + output;
        }
    }

    record Channel(String interfaceId, String channel) implements Source {
        @Override
        public String text() {
            return "@" + interfaceId + "." + channel;
        }
    }

    record Control() implements Source {
        @Override
        public String text() {
            return "control";
        }
    }
}
