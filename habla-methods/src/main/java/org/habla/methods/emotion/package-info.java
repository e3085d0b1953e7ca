/** The teacher's attitude: emotion recognised from words, the voice's loudness and pitch, touches and rewards. */
package org.habla.methods.emotion;
