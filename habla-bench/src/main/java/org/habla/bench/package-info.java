/**
 * Benchmarks of the engine, run by {@link org.habla.bench.Benchmarks#main} ({@code bench/run}), never by
 * the unit tests: end-to-end latency over loopback against a plain relay, in-process throughput, and
 * control-socket fan-out. They print figures; they assert nothing about speed.
 */
package org.habla.bench;
