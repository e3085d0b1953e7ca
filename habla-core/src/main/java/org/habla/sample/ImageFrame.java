package org.habla.sample;

import java.util.Arrays;
import java.util.Objects;

/**
 * One camera image.
 *
 * @see #encoding() {@code "jpeg"}, {@code "png"}, {@code "bgr8"} (raw, 3 bytes a pixel) or {@code "gray8"}
 */
public final class ImageFrame implements Payload {

    private final int width;
    private final int height;
    private final String encoding;
    private final byte[] data;

    private ImageFrame(int width, int height, String encoding, byte[] data) {
        if (width <= 0 || height <= 0 || width > 16_384 || height > 16_384) {
            throw new IllegalArgumentException("image size must be within 1..16384, was " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.encoding = Objects.requireNonNull(encoding, "encoding");
        this.data = data;
        int raw = switch (encoding) {
            case "bgr8" -> width * height * 3;
            case "gray8" -> width * height;
            default -> -1;
        };
        if (raw >= 0 && raw != data.length) {
            throw new IllegalArgumentException(encoding + " image of " + width + "x" + height
                    + " needs " + raw + " bytes, has " + data.length);
        }
    }

    public static ImageFrame of(int width, int height, String encoding, byte[] data) {
        return new ImageFrame(width, height, encoding, data.clone());
    }

    /** Takes ownership of {@code data}; the caller must not touch the array again. */
    public static ImageFrame wrap(int width, int height, String encoding, byte[] data) {
        return new ImageFrame(width, height, encoding, data);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public String encoding() {
        return encoding;
    }

    /** A copy of the encoded bytes. */
    public byte[] data() {
        return data.clone();
    }

    public int byteCount() {
        return data.length;
    }

    /** Writes the bytes to {@code out} without copying them first. */
    public void writeTo(java.io.OutputStream out) throws java.io.IOException {
        out.write(data);
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.IMAGE;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ImageFrame f && width == f.width && height == f.height
                && encoding.equals(f.encoding) && Arrays.equals(data, f.data);
    }

    @Override
    public int hashCode() {
        return Objects.hash(width, height, encoding, Arrays.hashCode(data));
    }

    @Override
    public String toString() {
        return "ImageFrame[" + width + "x" + height + " " + encoding + ", " + data.length + " bytes]";
    }
}
