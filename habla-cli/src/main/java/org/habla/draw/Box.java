package org.habla.draw;

/** A rectangle of the SVG picture, in pixels, origin top-left. */
public record Box(double x, double y, double w, double h) {

    public double right() {
        return x + w;
    }

    public double bottom() {
        return y + h;
    }

    public double centerX() {
        return x + w / 2;
    }

    /** Whether the two rectangles share any area (touching edges do not count). */
    public boolean overlaps(Box o) {
        return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }
}
