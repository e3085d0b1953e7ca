/** Daemon: the assembly of a config's method graph, its control servers and its status endpoint. */
package org.habla.daemon;
