/** The {@code text-lines} driver: a TCP stream of UTF-8 lines, e.g. a teacher typing rewards into {@code nc}. */
package org.habla.drivers.lines;
