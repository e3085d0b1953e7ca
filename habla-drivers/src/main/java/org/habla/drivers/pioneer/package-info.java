/** The {@code pioneer} driver: ARCOS (P2OS/AROS) over TCP, as a Pioneer 2 DX or MobileSim/AMRISim speaks it. */
package org.habla.drivers.pioneer;
