/** Speech recognition with Sphinx-4: the {@code speech-recognition} method and the decoder it runs in the background. */
package org.habla.methods.speech;
