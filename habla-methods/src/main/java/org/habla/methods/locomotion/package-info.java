/** How a legged robot walks: walk limits and the composition of a gait command from a planar motion. */
package org.habla.methods.locomotion;
