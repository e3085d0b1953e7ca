/** Net: the framing shared by every HABLA socket, and the per-method control servers built on it. */
package org.habla.net;
