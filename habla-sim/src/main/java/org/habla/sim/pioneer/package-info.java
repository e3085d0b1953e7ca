/**
 * The simulated Pioneer 2 DX: an ARCOS robot behind a TCP socket (handshake, SIPs, motion and sonar commands,
 * the watchdog), with the laptop's microphone and the teacher's keyboard as their own sockets.
 */
package org.habla.sim.pioneer;
