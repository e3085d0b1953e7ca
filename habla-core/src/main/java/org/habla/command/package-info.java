/**
 * Command: how a module adds a subcommand to {@code habla} ({@link org.habla.command.CommandExtension}), and the exit
 * codes every command shares.
 */
package org.habla.command;
