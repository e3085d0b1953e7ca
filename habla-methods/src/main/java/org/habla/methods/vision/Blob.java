package org.habla.methods.vision;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * One connected region of a colour class, in pixels with the origin at the top-left corner.
 *
 * @param label the colour class
 * @param cx    centroid column (mean of the region's pixels)
 * @param cy    centroid row
 * @param area  pixel count
 * @param x     left column of the bounding box
 * @param y     top row of the bounding box
 * @param w     bounding box width
 * @param h     bounding box height
 */
public record Blob(String label, double cx, double cy, int area, int x, int y, int w, int h) {

    /** The blob as the JSON object of a {@code blobs} record. */
    public ObjectNode toJson() {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        o.put("label", label);
        o.put("cx", Math.round(cx * 100) / 100.0);
        o.put("cy", Math.round(cy * 100) / 100.0);
        o.put("area", area);
        o.put("x", x);
        o.put("y", y);
        o.put("w", w);
        o.put("h", h);
        return o;
    }
}
