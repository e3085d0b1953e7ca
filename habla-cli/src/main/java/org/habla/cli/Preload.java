package org.habla.cli;

import org.slf4j.LoggerFactory;

/**
 * Work a daemon's start does on a thread of its own, beside the main thread, to load and link classes the main
 * thread needs a moment later (Jackson's readers, Jetty's server): on a computer with a second core the ports open
 * sooner (docs/performance.md (l)). What it makes is dropped; it never listens, connects or starts another thread.
 */
final class Preload {

    private Preload() {
    }

    /**
     * Runs {@code work} on a daemon thread named {@code habla-NAME-preload}. Logging is set up first, on the
     * caller's thread: a logger asked for while another thread sets logging up is a stand-in, and
     * {@code --log-level} must find logback's own.
     */
    static void inBackground(String name, Runnable work) {
        LoggerFactory.getILoggerFactory();
        Thread.ofPlatform().daemon().name("habla-" + name + "-preload").start(work);
    }
}
