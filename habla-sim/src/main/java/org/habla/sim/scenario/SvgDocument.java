package org.habla.sim.scenario;

import java.util.List;
import java.util.Locale;

/**
 * A small SVG 1.1 writer: the handful of shapes the report's plots need, with coordinates in user units
 * (pixels) and every text escaped. Not a general SVG library: no transforms, no styles beyond attributes.
 */
final class SvgDocument {

    private final int width;
    private final int height;
    private final StringBuilder body = new StringBuilder();

    SvgDocument(int width, int height) {
        this.width = width;
        this.height = height;
        rect(0, 0, width, height, "#ffffff", null);
    }

    SvgDocument line(double x1, double y1, double x2, double y2, String stroke, double strokeWidth) {
        body.append(String.format(Locale.ROOT,
                "  <line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.1f\"/>%n",
                x1, y1, x2, y2, escape(stroke), strokeWidth));
        return this;
    }

    /** A polyline through {@code points}, each an {x, y} pair; {@code title} (may be null) shows on hover. */
    SvgDocument polyline(List<double[]> points, String stroke, String title) {
        StringBuilder p = new StringBuilder();
        for (double[] xy : points) {
            p.append(String.format(Locale.ROOT, "%.1f,%.1f ", xy[0], xy[1]));
        }
        body.append("  <polyline fill=\"none\" stroke=\"").append(escape(stroke))
                .append("\" stroke-width=\"1.5\" points=\"").append(p.toString().trim()).append('"');
        return closeWithTitle("polyline", title);
    }

    SvgDocument rect(double x, double y, double w, double h, String fill, String title) {
        body.append(String.format(Locale.ROOT, "  <rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"",
                x, y, w, h, escape(fill)));
        return closeWithTitle("rect", title);
    }

    SvgDocument circle(double cx, double cy, double r, String fill, String title) {
        body.append(String.format(Locale.ROOT, "  <circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"",
                cx, cy, r, escape(fill)));
        return closeWithTitle("circle", title);
    }

    /** Text at (x, y), anchored {@code start}, {@code middle} or {@code end}; {@code rotate} turns it -90°. */
    SvgDocument text(double x, double y, String anchor, int size, String content, boolean rotate) {
        body.append(String.format(Locale.ROOT,
                "  <text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\" font-family=\"sans-serif\" font-size=\"%d\"%s>",
                x, y, anchor, size, rotate ? String.format(Locale.ROOT,
                        " transform=\"rotate(-90 %.1f %.1f)\"", x, y) : ""))
                .append(escape(content)).append("</text>\n");
        return this;
    }

    private SvgDocument closeWithTitle(String element, String title) {
        if (title == null) {
            body.append("/>\n");
        } else {
            body.append("><title>").append(escape(title)).append("</title></").append(element).append(">\n");
        }
        return this;
    }

    static String escape(String s) {
        StringBuilder out = new StringBuilder(s.length());
        for (char c : s.toCharArray()) {
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                default -> out.append(c < 0x20 && c != '\t' && c != '\n' ? ' ' : c);
            }
        }
        return out.toString();
    }

    /** The whole document. */
    String render() {
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + width + "\" height=\""
                + height + "\" viewBox=\"0 0 " + width + " " + height + "\">\n" + body + "</svg>\n";
    }
}
