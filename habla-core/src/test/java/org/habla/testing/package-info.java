/** Testing: helpers shared by the modules' tests (processes, ports), published in the core test jar. */
package org.habla.testing;
