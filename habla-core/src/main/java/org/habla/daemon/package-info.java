/**
 * Daemon: the assembly of a config's method graph, its control servers, its status endpoint and the products that
 * run beside it.
 */
package org.habla.daemon;
