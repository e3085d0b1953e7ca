/** The simulated Sony Aibo ERS-7: Tekkotsu's servers on loopback, byte for byte, over a walking body. */
package org.habla.sim.aibo;
