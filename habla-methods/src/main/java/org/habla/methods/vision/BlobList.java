package org.habla.methods.vision;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The {@code blobs} record of {@code image-segmentation}: the frame's size and the regions of every colour class,
 * largest first, in pixels from the image's top-left corner, x to the right and y down.
 *
 * <pre>{@code {"width": 208, "height": 160, "blobs": [{"label": "pink", "cx": 20.5, "cy": 9.0, "area": 189,
 *   "x": 10, "y": 5, "w": 21, "h": 9}]}}</pre>
 *
 * @param width  frame width, pixels (0 when a record read from JSON does not say)
 * @param height frame height, pixels (0 when a record read from JSON does not say)
 * @param blobs  the regions, largest first
 */
public record BlobList(int width, int height, List<Entry> blobs) implements RecordForm {

    private static final String PIXELS = "pixels from the image's top-left corner, x to the right, y down";

    /** The fields of a blobs record. */
    public static final RecordLayout<BlobList> LAYOUT = RecordLayout.of(BlobList.class)
            .integer("width", BlobList::width).unit("px").doc("the frame's width")
            .integer("height", BlobList::height).unit("px").doc("the frame's height")
            .array("blobs", BlobList::blobsJson).unit("px").frame(PIXELS)
            .doc("the regions, largest first: {label, cx, cy (centroid), area, x, y, w, h (bounding box)}")
            .build();

    /**
     * One region: its colour class, centroid, pixel count and bounding box. A whole number is written as one.
     *
     * @param label the colour class
     */
    public record Entry(String label, double cx, double cy, double area, double x, double y, double w, double h) {

        /** The blob as a record carries it: the centroid to a hundredth of a pixel. */
        static Entry of(Blob b) {
            return new Entry(b.label(), Math.round(b.cx() * 100) / 100.0, Math.round(b.cy() * 100) / 100.0, b.area(),
                    b.x(), b.y(), b.w(), b.h());
        }

        /** Whether the centroid is finite (an entry read from JSON may lack it). */
        public boolean centred() {
            return Double.isFinite(cx) && Double.isFinite(cy);
        }

        /** Whether the centroid and the bounding box are finite (an entry read from JSON may lack some). */
        public boolean boxed() {
            return centred() && Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(w) && Double.isFinite(h);
        }

        ObjectNode toJson() {
            ObjectNode o = JsonNodeFactory.instance.objectNode().put("label", label).put("cx", cx).put("cy", cy);
            whole(o, "area", area);
            whole(o, "x", x);
            whole(o, "y", y);
            whole(o, "w", w);
            return whole(o, "h", h);
        }

        private static ObjectNode whole(ObjectNode o, String name, double v) {
            return v == Math.rint(v) && Math.abs(v) <= Integer.MAX_VALUE ? o.put(name, (int) v) : o.put(name, v);
        }

        static Entry fromJson(JsonNode b) {
            return new Entry(b.path("label").asText(), number(b, "cx"), number(b, "cy"), number(b, "area"),
                    number(b, "x"), number(b, "y"), number(b, "w"), number(b, "h"));
        }

        private static double number(JsonNode b, String field) {
            JsonNode n = b.path(field);
            return n.isNumber() ? n.doubleValue() : Double.NaN;
        }
    }

    public BlobList {
        blobs = List.copyOf(blobs);
    }

    @Override
    public RecordLayout<BlobList> layout() {
        return LAYOUT;
    }

    private ArrayNode blobsJson() {
        ArrayNode a = JsonNodeFactory.instance.arrayNode(blobs.size());
        blobs.forEach(b -> a.add(b.toJson()));
        return a;
    }

    /** The first region of {@code label} (any label when empty) that is {@code usable}: the largest such. */
    public Optional<Entry> largest(String label, Predicate<Entry> usable) {
        return blobs.stream().filter(b -> (label.isEmpty() || label.equals(b.label())) && usable.test(b)).findFirst();
    }

    /**
     * The blobs a record carries: the form itself inside the daemon, else read from its JSON; empty when the record
     * has no {@code blobs} array.
     */
    public static Optional<BlobList> fromRecord(RecordValue record) {
        Optional<BlobList> typed = record.form(BlobList.class);
        if (typed.isPresent()) {
            return typed;
        }
        JsonNode list = record.get("blobs");
        if (!list.isArray()) {
            return Optional.empty();
        }
        List<Entry> entries = new ArrayList<>();
        list.forEach(b -> entries.add(Entry.fromJson(b)));
        JsonNode w = record.get("width");
        JsonNode h = record.get("height");
        return Optional.of(new BlobList(w.isInt() ? w.intValue() : 0, h.isInt() ? h.intValue() : 0, entries));
    }
}
