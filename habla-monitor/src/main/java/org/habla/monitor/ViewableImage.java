package org.habla.monitor;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.habla.sample.ImageFrame;

/**
 * A camera frame as a browser or Foxglove shows it: JPEG and PNG frames as they are, raw {@code bgr8} and
 * {@code gray8} frames encoded to PNG (on the monitor's thread, never the engine's).
 *
 * @param format {@code "jpeg"} or {@code "png"}
 * @param bytes  the encoded image
 */
record ViewableImage(String format, byte[] bytes, int width, int height) {

    static ViewableImage of(ImageFrame frame) throws IOException {
        return switch (frame.encoding()) {
            case "jpeg", "png" -> new ViewableImage(frame.encoding(), frame.data(), frame.width(), frame.height());
            case "bgr8", "gray8" -> new ViewableImage("png", png(frame), frame.width(), frame.height());
            default -> throw new IOException("an image in '" + frame.encoding() + "' cannot be shown");
        };
    }

    String mimeType() {
        return "image/" + format;
    }

    private static byte[] png(ImageFrame frame) throws IOException {
        boolean gray = frame.encoding().equals("gray8");
        BufferedImage img = new BufferedImage(frame.width(), frame.height(),
                gray ? BufferedImage.TYPE_BYTE_GRAY : BufferedImage.TYPE_3BYTE_BGR);
        byte[] target = ((DataBufferByte) img.getRaster().getDataBuffer()).getData();
        System.arraycopy(frame.data(), 0, target, 0, target.length);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "png", out);
        return out.toByteArray();
    }
}
