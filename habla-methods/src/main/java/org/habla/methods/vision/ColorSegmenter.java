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
 * label 8-connected components and keep those of at least {@code minAreaPx}. Holds no state between
 * frames, so it may run on any thread; the natives must be loaded ({@link OpenCvLibrary#load()}).
 */
public final class ColorSegmenter {

    private final ImageSegmentationParams params;
    private final Mat openKernel;
    private final Mat closeKernel;

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
        Mat hsv = new Mat();
        Imgproc.cvtColor(bgr, hsv, Imgproc.COLOR_BGR2HSV);
        List<Blob> blobs = new ArrayList<>();
        for (Map.Entry<String, ColorRange> c : params.colors().entrySet()) {
            Mat mask = threshold(hsv, c.getValue());
            clean(mask);
            collect(c.getKey(), mask, blobs);
            mask.release();
        }
        blobs.sort(Comparator.comparingInt(Blob::area).reversed());
        Segmentation s = new Segmentation(bgr.cols(), bgr.rows(),
                blobs.subList(0, Math.min(blobs.size(), params.maxBlobs())), "");
        bgr.release();
        hsv.release();
        return s;
    }

    private static Mat decode(ImageFrame frame) {
        byte[] data = frame.data();
        return switch (frame.encoding()) {
            case "jpeg", "png" -> Imgcodecs.imdecode(new MatOfByte(data), Imgcodecs.IMREAD_COLOR);
            case "bgr8" -> {
                Mat m = new Mat(frame.height(), frame.width(), CvType.CV_8UC3);
                m.put(0, 0, data);
                yield m;
            }
            case "gray8" -> {
                Mat g = new Mat(frame.height(), frame.width(), CvType.CV_8UC1);
                g.put(0, 0, data);
                Mat m = new Mat();
                Imgproc.cvtColor(g, m, Imgproc.COLOR_GRAY2BGR);
                g.release();
                yield m;
            }
            default -> null;
        };
    }

    private static Mat threshold(Mat hsv, ColorRange r) {
        Mat mask = new Mat();
        if (!r.wraps()) {
            Core.inRange(hsv, new Scalar(r.hMin(), r.sMin(), r.vMin()), new Scalar(r.hMax(), r.sMax(), r.vMax()), mask);
            return mask;
        }
        Mat high = new Mat();
        Core.inRange(hsv, new Scalar(r.hMin(), r.sMin(), r.vMin()),
                new Scalar(ColorRange.HUE_MAX, r.sMax(), r.vMax()), mask);
        Core.inRange(hsv, new Scalar(0, r.sMin(), r.vMin()), new Scalar(r.hMax(), r.sMax(), r.vMax()), high);
        Core.bitwise_or(mask, high, mask);
        high.release();
        return mask;
    }

    private void clean(Mat mask) {
        if (openKernel != null) {
            Imgproc.morphologyEx(mask, mask, Imgproc.MORPH_OPEN, openKernel);
        }
        if (closeKernel != null) {
            // Outside the frame is "not this colour": without the zero margin OpenCV's closing would
            // glue a region lying a pixel or two from the edge to the edge.
            int pad = params.closePx() / 2 + 1;
            Mat padded = new Mat();
            Core.copyMakeBorder(mask, padded, pad, pad, pad, pad, Core.BORDER_CONSTANT, new Scalar(0));
            Imgproc.morphologyEx(padded, padded, Imgproc.MORPH_CLOSE, closeKernel);
            padded.submat(pad, pad + mask.rows(), pad, pad + mask.cols()).copyTo(mask);
            padded.release();
        }
    }

    private void collect(String label, Mat mask, List<Blob> into) {
        Mat labels = new Mat();
        Mat stats = new Mat();
        Mat centroids = new Mat();
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
        labels.release();
        stats.release();
        centroids.release();
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
