/** Samples: the immutable messages that flow through the method graph, and their payload kinds. */
package org.habla.sample;
