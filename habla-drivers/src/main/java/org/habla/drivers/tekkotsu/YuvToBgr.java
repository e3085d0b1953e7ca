package org.habla.drivers.tekkotsu;

/**
 * The conversion of the raw camera's uncompressed Y, U (Cb), V (Cr) planes to interleaved BGR bytes
 * at the Y plane's size: chroma upsampled by nearest pixel, colour by the JFIF YCbCr→RGB matrix.
 */
final class YuvToBgr {

    private YuvToBgr() {
    }

    static byte[] convert(CameraPacket.Section y, CameraPacket.Section u, CameraPacket.Section v) {
        int w = y.width();
        int h = y.height();
        byte[] yd = y.data();
        byte[] ud = u.data();
        byte[] vd = v.data();
        byte[] out = new byte[w * h * 3];
        for (int row = 0; row < h; row++) {
            int uRow = row * u.height() / h;
            int vRow = row * v.height() / h;
            for (int col = 0; col < w; col++) {
                double luma = yd[row * w + col] & 0xff;
                double cb = (ud[uRow * u.width() + col * u.width() / w] & 0xff) - 128;
                double cr = (vd[vRow * v.width() + col * v.width() / w] & 0xff) - 128;
                int at = (row * w + col) * 3;
                out[at] = clamp(luma + 1.772 * cb);
                out[at + 1] = clamp(luma - 0.344136 * cb - 0.714136 * cr);
                out[at + 2] = clamp(luma + 1.402 * cr);
            }
        }
        return out;
    }

    private static byte clamp(double value) {
        return (byte) Math.max(0, Math.min(255, Math.round(value)));
    }
}
