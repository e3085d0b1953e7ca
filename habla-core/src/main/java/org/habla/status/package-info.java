/** Status: the loopback endpoint that hands {@code habla status} a snapshot of the running daemon. */
package org.habla.status;
