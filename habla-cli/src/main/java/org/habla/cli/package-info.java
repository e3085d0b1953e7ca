/**
 * CLI: the {@code habla} command line (the launcher's entry point, {@link org.habla.cli.Habla}) and its commands;
 * where the daemon meets the products beside it (the monitor, the recording).
 */
package org.habla.cli;
