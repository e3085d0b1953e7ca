package org.habla.methods.vision;

/**
 * The OpenCV native library, loaded once per process from the natives bundled in the
 * {@code org.openpnp:opencv} jar. Loading takes a few hundred milliseconds, so methods call
 * {@link #load()} from background work and report themselves not ready until it returns.
 */
public final class OpenCvLibrary {

    private static volatile boolean loaded;

    private OpenCvLibrary() {
    }

    /** Loads the natives if no one has yet; returns the OpenCV version. Safe from any thread. */
    public static String load() {
        if (!loaded) {
            synchronized (OpenCvLibrary.class) {
                if (!loaded) {
                    nu.pattern.OpenCV.loadLocally();
                    loaded = true;
                }
            }
        }
        return org.opencv.core.Core.VERSION;
    }
}
