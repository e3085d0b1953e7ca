/** Recognition of musical notes in audio: the names of the equal-tempered scale and the {@code note-recognition} method that hears them. */
package org.habla.methods.notes;
