package org.habla.command;

/** The exit codes of every {@code habla} command. */
public final class ExitCodes {

    /** Everything went as asked. */
    public static final int OK = 0;
    /** The run failed (a link, a socket, an I/O error). */
    public static final int RUNTIME_FAILURE = 1;
    /** The command line or the config is wrong. */
    public static final int USAGE_OR_CONFIG = 2;

    private ExitCodes() {
    }
}
