/**
 * General methods for a room (knowing nothing of any one room): presence from motion sensors and door contacts,
 * light, climate and sound sensors, lamps, blinds and a speaker, and the virtual layer's occupancy per zone,
 * comfort and the room's action socket.
 */
package org.habla.methods.room;
