/** Methods of the sensors &amp; actuators layer: general sensors that store and clean interface readings, and general actuators that shape commands for interface channels. */
package org.habla.methods.sensors;
