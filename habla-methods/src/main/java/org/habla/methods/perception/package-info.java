/** Processing methods that turn sensor readings into what is around the robot: the nearest obstacle, where things are. */
package org.habla.methods.perception;
