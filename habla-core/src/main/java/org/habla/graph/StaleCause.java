package org.habla.graph;

/**
 * Why a method's outputs are stale: what upstream of it is down, unavailable or lost, and a sentence that says so.
 *
 * @param source the interface ({@code "@robot"}), the reading channel whose device is unavailable
 *               ({@code "@room.motion"}) or the placed method whose worker is lost ({@code "speech"})
 * @param why    the sentence for the status, the log and the clients' stale notices
 */
record StaleCause(String source, String why) {
}
