/** Actuator methods of the sensors &amp; actuators layer: they shape commands and write them to interface command channels. */
package org.habla.methods.actuators;
