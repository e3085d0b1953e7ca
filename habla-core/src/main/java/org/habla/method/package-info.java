/** Methods: the three layer base classes, their ports, their life cycle and the plugin interface that makes them. */
package org.habla.method;
