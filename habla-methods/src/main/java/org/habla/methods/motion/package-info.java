/** Methods and values that shape motion commands for a mobile base: speed limits, acceleration ramps, collision vetoes. */
package org.habla.methods.motion;
