/** Drivers: the plugin interface that turns a robot's native protocol into named channels, and back. */
package org.habla.driver;
