/**
 * Recording: the append-only file of everything that crossed a running graph's edges — readings and
 * commands on the hardware side, control writes and exposed outputs on the control side — with its
 * writer (a tap that never blocks the engine) and a reader that survives a torn last record.
 */
package org.habla.recording;
