/** The robot's voice: short tone melodies synthesised in Java for words and emotions, with no speech engine. */
package org.habla.methods.voice;
