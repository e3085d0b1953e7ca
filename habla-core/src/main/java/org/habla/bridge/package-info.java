/**
 * Bridges: the plugin interface for carrying exposed methods' samples and actions over something other than
 * HABLA's own control sockets (an MQTT broker, say), to every control architecture that subscribes there.
 */
package org.habla.bridge;
