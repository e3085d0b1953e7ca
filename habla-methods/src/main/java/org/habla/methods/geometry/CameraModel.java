package org.habla.methods.geometry;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * A pinhole camera: its fields of view, its image size and its height above the floor. It turns a
 * pixel into a viewing direction and back, which is all the geometry that locating an object seen in
 * an image needs. It travels between methods as the {@code camera} record, with the same field names
 * a camera channel's metadata uses:
 *
 * <pre>{@code
 * {"hfovRad": 0.993, "vfovRad": 0.789, "width": 208, "height": 160, "heightM": 0.2}
 * }</pre>
 *
 * Pixel coordinates have their origin at the top-left corner, x to the right and y down.
 *
 * @param hfovRad horizontal field of view, radians
 * @param vfovRad vertical field of view, radians
 * @param width   image width, pixels
 * @param height  image height, pixels
 * @param heightM height of the lens above the floor, metres
 */
public record CameraModel(double hfovRad, double vfovRad, int width, int height, double heightM)
        implements RecordForm {

    /** The fields of a camera record. */
    public static final RecordLayout<CameraModel> LAYOUT = RecordLayout.of(CameraModel.class)
            .number("hfovRad", CameraModel::hfovRad).unit("rad").doc("horizontal field of view")
            .number("vfovRad", CameraModel::vfovRad).unit("rad").doc("vertical field of view")
            .integer("width", CameraModel::width).unit("px").doc("image width")
            .integer("height", CameraModel::height).unit("px").doc("image height")
            .number("heightM", CameraModel::heightM).unit("m").frame("above the floor").doc("height of the lens")
            .build();

    public CameraModel {
        if (!(hfovRad > 0 && hfovRad < Math.PI) || !(vfovRad > 0 && vfovRad < Math.PI)) {
            throw new IllegalArgumentException("fields of view must be within (0, π), were " + hfovRad + ", " + vfovRad);
        }
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, was " + width + "x" + height);
        }
        if (!(heightM >= 0) || !Double.isFinite(heightM)) {
            throw new IllegalArgumentException("heightM must be a finite number of at least 0, was " + heightM);
        }
    }

    /** Focal length in pixels along x. */
    public double focalXPx() {
        return width / 2.0 / Math.tan(hfovRad / 2);
    }

    /** Focal length in pixels along y. */
    public double focalYPx() {
        return height / 2.0 / Math.tan(vfovRad / 2);
    }

    /** The same camera with images of another size (the field of view stays). */
    public CameraModel withSize(int newWidth, int newHeight) {
        return new CameraModel(hfovRad, vfovRad, newWidth, newHeight, heightM);
    }

    /**
     * The direction of the ray through pixel ({@code px}, {@code py}) in the camera frame: x along the
     * optical axis, y to the left, z up; not normalised (x is 1).
     */
    public double[] ray(double px, double py) {
        return new double[] {1, (width / 2.0 - px) / focalXPx(), (height / 2.0 - py) / focalYPx()};
    }

    /** The pixel where a point of the camera frame (x forward, y left, z up, x &gt; 0) appears. */
    public double[] project(double x, double y, double z) {
        return new double[] {width / 2.0 - focalXPx() * y / x, height / 2.0 - focalYPx() * z / x};
    }

    /** The {@code camera} record, carrying this model itself. */
    public RecordValue toRecord() {
        return RecordValue.of(this);
    }

    /** The model a {@code camera} record carries; empty when its fields do not make a camera. */
    public static Optional<CameraModel> fromRecord(RecordValue record) {
        Optional<CameraModel> typed = record.form(CameraModel.class);
        return typed.isPresent() ? typed : fromJson(record.jsonView(), null);
    }

    @Override
    public RecordLayout<CameraModel> layout() {
        return LAYOUT;
    }

    /**
     * Reads a {@code camera} record or a camera channel's metadata; each field left out or not a
     * valid number falls back to {@code fallback}'s. Empty when the fields do not make a camera.
     */
    public static Optional<CameraModel> fromJson(JsonNode node, CameraModel fallback) {
        try {
            return Optional.of(new CameraModel(
                    number(node, "hfovRad", fallback == null ? Double.NaN : fallback.hfovRad),
                    number(node, "vfovRad", fallback == null ? Double.NaN : fallback.vfovRad),
                    (int) number(node, "width", fallback == null ? 0 : fallback.width),
                    (int) number(node, "height", fallback == null ? 0 : fallback.height),
                    number(node, "heightM", fallback == null ? 0 : fallback.heightM)));
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    private static double number(JsonNode node, String field, double fallback) {
        JsonNode n = node == null ? null : node.get(field);
        return n != null && n.isNumber() && Double.isFinite(n.doubleValue()) ? n.doubleValue() : fallback;
    }
}
