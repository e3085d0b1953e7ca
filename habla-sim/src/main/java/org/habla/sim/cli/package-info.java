/** The {@code habla sim} command: runs a simulated robot and its world from the command line. */
package org.habla.sim.cli;
