package org.habla.command;

/**
 * Adds a subcommand to {@code habla} from another module (e.g. {@code sim}, {@code scenario}, {@code run},
 * {@code replay}). Registered through {@code META-INF/services/org.habla.command.CommandExtension}.
 * The returned object is a picocli {@code @Command}-annotated instance; it exits through its
 * {@code Callable<Integer>} with the codes of {@link ExitCodes}.
 */
public interface CommandExtension {

    /** The subcommand name. */
    String name();

    /** A fresh picocli command object. */
    Object command();
}
