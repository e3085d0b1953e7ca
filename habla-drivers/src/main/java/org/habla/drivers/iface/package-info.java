/** The driver of HABLA's own interface protocol ({@code habla-interface/1}), for hardware that has no driver of its own. */
package org.habla.drivers.iface;
