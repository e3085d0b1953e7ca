/** Planar geometry the methods share: poses in the robot frame and range scans with their sensor poses. */
package org.habla.methods.geometry;
