/**
 * Graph: the engine that runs a config's methods — one turn at a time per method — wires their
 * outputs to inputs, interface channels and control sockets, keeps the hardware links up and
 * runs the motion watchdog.
 */
package org.habla.graph;
