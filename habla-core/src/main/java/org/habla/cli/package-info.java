/** CLI: the {@code habla} command and the extension point through which other modules add subcommands. */
package org.habla.cli;
