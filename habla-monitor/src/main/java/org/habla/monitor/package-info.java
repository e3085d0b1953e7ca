/** The live monitor: a read-only web page and a Foxglove WebSocket server that show a running graph. */
package org.habla.monitor;
