/** The simulator's command line: {@code habla sim pioneer} and {@code habla sim aibo}. */
package org.habla.sim.cli;
