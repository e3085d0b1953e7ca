/**
 * The simulated world shared by HABLA's robot simulators: the arena and the target object, a planar robot body
 * that collides with them, sim time that runs faster than real time, the scripted teacher, and the ground-truth
 * line server that tells tests and scenarios where everything really is.
 */
package org.habla.sim.world;
