/**
 * Drawing: the three-layer picture of a config's method graph (interfaces below, control sockets above,
 * sensing arrows up and actuation arrows down) as Graphviz dot, Mermaid or a self-laid-out SVG.
 */
package org.habla.draw;
