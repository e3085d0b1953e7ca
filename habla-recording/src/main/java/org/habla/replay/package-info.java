/**
 * Replay: runs the daemon with a recording in place of the robot — the recorded readings fed into the same
 * channels at the recorded times, the same control sockets — and compares what comes out with the recording.
 */
package org.habla.replay;
