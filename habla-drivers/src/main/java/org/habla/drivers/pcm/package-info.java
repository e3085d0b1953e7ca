/** The {@code pcm-stream} driver: raw PCM audio over TCP, e.g. a laptop microphone piped through {@code nc}. */
package org.habla.drivers.pcm;
