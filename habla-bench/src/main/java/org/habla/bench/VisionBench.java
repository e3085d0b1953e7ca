package org.habla.bench;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.util.Random;
import javax.imageio.ImageIO;
import org.HdrHistogram.Histogram;
import org.habla.methods.vision.ColorSegmenter;
import org.habla.methods.vision.ImageSegmentationParams;
import org.habla.methods.vision.OpenCvLibrary;
import org.habla.methods.vision.Segmentation;
import org.habla.sample.ImageFrame;

/**
 * Benchmark (d): the cost of one {@code image-segmentation} frame — JPEG decode, HSV threshold,
 * opening, closing, connected components — at the Aibo camera's two sizes, on the calling thread.
 */
final class VisionBench {

    private final int frames;

    VisionBench(int frames) {
        this.frames = frames;
    }

    void run() throws Exception {
        System.out.printf("%n(d) image-segmentation per frame (default params, one colour class), %d frames per size%n", frames);
        System.out.printf("  OpenCV %s%n", OpenCvLibrary.load());
        System.out.printf("%-12s %10s %10s %10s %10s%n", "size", "JPEG bytes", "p50 µs", "p99 µs", "frames/s");
        ColorSegmenter segmenter = new ColorSegmenter(ImageSegmentationParams.defaults());
        for (int[] size : new int[][] {{208, 160}, {416, 320}}) {
            ImageFrame[] variants = new ImageFrame[16];
            Random random = new Random(size[0]);
            for (int i = 0; i < variants.length; i++) {
                variants[i] = frame(size[0], size[1], random);
            }
            for (int i = 0; i < 200; i++) {
                segmenter.segment(variants[i % variants.length]);
            }
            Histogram h = new Histogram(10_000_000L, 3);
            long found = 0;
            long t0 = System.nanoTime();
            for (int i = 0; i < frames; i++) {
                long s = System.nanoTime();
                Segmentation seg = segmenter.segment(variants[i % variants.length]);
                h.recordValue((System.nanoTime() - s) / 1_000);
                found += seg.blobs().size();
            }
            double seconds = (System.nanoTime() - t0) / 1e9;
            System.out.printf("%-12s %10d %10d %10d %,10.0f%s%n", size[0] + "x" + size[1], variants[0].byteCount(),
                    h.getValueAtPercentile(50), h.getValueAtPercentile(99), frames / seconds,
                    found == frames ? "" : "  (found " + found + " blobs in " + frames + " frames)");
        }
    }

    /** A grey wall over a brown floor and a pink ball, with noise, as JPEG. */
    private static ImageFrame frame(int w, int h, Random random) throws Exception {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(170, 172, 176));
        g.fillRect(0, 0, w, h / 2);
        g.setColor(new Color(125, 104, 84));
        g.fillRect(0, h / 2, w, h - h / 2);
        g.setColor(new Color(255, 105, 180));
        int r = w / 20 + random.nextInt(w / 20);
        g.fillOval(r + random.nextInt(w - 3 * r), h / 2 - r + random.nextInt(h / 2 - r), 2 * r, 2 * r);
        g.dispose();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int c = img.getRGB(x, y);
                int n = (int) (random.nextGaussian() * 6);
                int red = Math.max(0, Math.min(255, ((c >> 16) & 0xff) + n));
                int green = Math.max(0, Math.min(255, ((c >> 8) & 0xff) + n));
                int blue = Math.max(0, Math.min(255, (c & 0xff) + n));
                img.setRGB(x, y, (red << 16) | (green << 8) | blue);
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "jpeg", out);
        return ImageFrame.wrap(w, h, "jpeg", out.toByteArray());
    }
}
