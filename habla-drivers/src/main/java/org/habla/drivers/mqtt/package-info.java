/**
 * The {@code mqtt} driver (a room's devices on an MQTT broker: state topics mapped to reading channels, command
 * channels published on {@code …/set} topics, availability topics turned into staleness) and the control side's
 * MQTT bridge, both over one small adapter of the HiveMQ MQTT client.
 */
package org.habla.drivers.mqtt;
