/**
 * The simulated room: zones, a person who walks between them and out of the door, daylight that changes, lamps
 * that light their zone, and a teacher with a button, published and obeyed on an MQTT broker exactly as
 * Zigbee2MQTT devices would be.
 */
package org.habla.sim.room;
