package org.habla.methods.vision;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.habla.sample.ImageFrame;
import org.opencv.core.Core;
import org.opencv.core.CvType;
import org.opencv.core.Mat;
import org.opencv.core.MatOfByte;
import org.opencv.core.Scalar;
import org.opencv.core.Size;
import org.opencv.imgcodecs.Imgcodecs;
import org.opencv.imgproc.Imgproc;

/**
 * Finds the blobs of colour classes in a frame with OpenCV: decode to BGR, convert to HSV, threshold
 * each class (two ranges when its hue wraps around red), open to remove specks, close to fill holes,
 * label 8-connected components and keep those of at least {@code minAreaPx}. The natives must be loaded
 * ({@link OpenCvLibrary#load()}).
 *
 * <p>One frame at a time (any thread, one after another): the matrices a frame needs are made once and
 * reused for the next, and a matrix made for one frame is released before {@link #segment} returns. A
 * matrix left to the garbage collector keeps its native memory until the collector runs its finalizer,
 * which, for one promoted to the old generation, may be minutes away: at 30 frames a second that was the
 * daemon's resident memory growing.
 */
public final class ColorSegmenter {

    private final ImageSegmentationParams params;
    private final Mat openKernel;
    private final Mat closeKernel;
    private final MatOfByte encoded = new MatOfByte();
    private final Mat gray = new Mat();
    private final Mat hsv = new Mat();
    private final Mat mask = new Mat();
    private final Mat high = new Mat();
    private final Mat padded = new Mat();
    private final Mat labels = new Mat();
    private final Mat stats = new Mat();
    private final Mat centroids = new Mat();

    public ColorSegmenter(ImageSegmentationParams params) {
        this.params = params;
        this.openKernel = kernel(params.openPx());
        this.closeKernel = kernel(params.closePx());
    }

    /** The blobs of {@code frame}; an undecodable frame gives a result with an error, never an exception. */
    public Segmentation segment(ImageFrame frame) {
        Mat bgr = decode(frame);
        if (bgr == null || bgr.empty()) {
            release(bgr);
            return Segmentation.unreadable("cannot decode " + frame);
        }
        Imgproc.cvtColor(bgr, hsv, Imgproc.COLOR_BGR2HSV);
        List<Blob> blobs = new ArrayList<>();
        for (Map.Entry<String, ColorRange> c : params.colors().entrySet()) {
            threshold(c.getValue());
            clean();
            collect(c.getKey(), blobs);
        }
        blobs.sort(Comparator.comparingInt(Blob::area).reversed());
        Segmentation s = new Segmentation(bgr.cols(), bgr.rows(),
                blobs.subList(0, Math.min(blobs.size(), params.maxBlobs())), "");
        bgr.release();
        return s;
    }

    /** The frame as a new BGR matrix (the caller releases it), or null for an unknown encoding. */
    private Mat decode(ImageFrame frame) {
        return switch (frame.encoding()) {
            case "jpeg", "png" -> {
                encoded.create(frame.byteCount(), 1, CvType.CV_8UC1);
                copyInto(encoded, frame);
                yield Imgcodecs.imdecode(encoded, Imgcodecs.IMREAD_COLOR);
            }
            case "bgr8" -> {
                Mat m = new Mat(frame.height(), frame.width(), CvType.CV_8UC3);
                m.put(0, 0, frame.data());
                yield m;
            }
            case "gray8" -> {
                gray.create(frame.height(), frame.width(), CvType.CV_8UC1);
                gray.put(0, 0, frame.data());
                Mat m = new Mat();
                Imgproc.cvtColor(gray, m, Imgproc.COLOR_GRAY2BGR);
                yield m;
            }
            default -> null;
        };
    }

    /** The frame's bytes into the continuous matrix {@code m}, with no copy on the Java heap between. */
    private static void copyInto(Mat m, ImageFrame frame) {
        try {
            frame.writeTo(new java.io.OutputStream() {
                private int at;

                @Override
                public void write(int b) {
                    write(new byte[] {(byte) b}, 0, 1);
                }

                @Override
                public void write(byte[] b, int off, int len) {
                    m.put(at, 0, b, off, len);
                    at += len;
                }
            });
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The pixels of {@code hsv} in {@code r}, into {@code mask}. */
    private void threshold(ColorRange r) {
        if (!r.wraps()) {
            Core.inRange(hsv, new Scalar(r.hMin(), r.sMin(), r.vMin()), new Scalar(r.hMax(), r.sMax(), r.vMax()), mask);
            return;
        }
        Core.inRange(hsv, new Scalar(r.hMin(), r.sMin(), r.vMin()),
                new Scalar(ColorRange.HUE_MAX, r.sMax(), r.vMax()), mask);
        Core.inRange(hsv, new Scalar(0, r.sMin(), r.vMin()), new Scalar(r.hMax(), r.sMax(), r.vMax()), high);
        Core.bitwise_or(mask, high, mask);
    }

    private void clean() {
        if (openKernel != null) {
            Imgproc.morphologyEx(mask, mask, Imgproc.MORPH_OPEN, openKernel);
        }
        if (closeKernel != null) {
            // Outside the frame is "not this colour": without the zero margin OpenCV's closing would
            // glue a region lying a pixel or two from the edge to the edge.
            int pad = params.closePx() / 2 + 1;
            Core.copyMakeBorder(mask, padded, pad, pad, pad, pad, Core.BORDER_CONSTANT, new Scalar(0));
            Imgproc.morphologyEx(padded, padded, Imgproc.MORPH_CLOSE, closeKernel);
            Mat inner = padded.submat(pad, pad + mask.rows(), pad, pad + mask.cols());
            inner.copyTo(mask);
            inner.release();
        }
    }

    private void collect(String label, List<Blob> into) {
        int n = Imgproc.connectedComponentsWithStats(mask, labels, stats, centroids, 8, CvType.CV_32S);
        int[] row = new int[5];
        double[] centre = new double[2];
        for (int i = 1; i < n; i++) {
            stats.get(i, 0, row);
            int area = row[Imgproc.CC_STAT_AREA];
            if (area < params.minAreaPx()) {
                continue;
            }
            centroids.get(i, 0, centre);
            into.add(new Blob(label, centre[0], centre[1], area, row[Imgproc.CC_STAT_LEFT], row[Imgproc.CC_STAT_TOP],
                    row[Imgproc.CC_STAT_WIDTH], row[Imgproc.CC_STAT_HEIGHT]));
        }
    }

    private static Mat kernel(int side) {
        return side <= 1 ? null : Imgproc.getStructuringElement(Imgproc.MORPH_ELLIPSE, new Size(side, side));
    }

    private static void release(Mat m) {
        if (m != null) {
            m.release();
        }
    }
}
