/** Methods of the virtual information layer: the high-level information and actions a control architecture reads and writes on its sockets. */
package org.habla.methods.virtual;
