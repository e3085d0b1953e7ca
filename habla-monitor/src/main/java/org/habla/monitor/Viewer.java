package org.habla.monitor;

/**
 * One connected page, as the monitor's thread sees it. An update is offered, never queued: a page still
 * taking the previous one misses this one (the next carries the newer state), so a slow browser costs only
 * its own updates.
 */
interface Viewer {

    /** Hands the text to the page unless it is still busy with the previous one; false if skipped. */
    boolean offer(String text);

    /** Whether the page is still taking the previous update. */
    boolean busy();

    /** The method whose details the page asked for, or null. */
    String selected();
}
