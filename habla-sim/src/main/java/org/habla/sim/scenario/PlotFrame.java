package org.habla.sim.scenario;

import java.util.List;
import org.habla.draw.SvgDocument;

/**
 * The frame of a plot: title, axes, grid lines and tick labels around a plotting area, the mapping of
 * data values to pixels, and the handful of shapes the report's plots draw, written by HABLA's
 * {@link SvgDocument}. The x axis is either numeric (with {@link Ticks}) or categorical (no ticks: the
 * caller places its categories in [0, 1] and labels them).
 */
final class PlotFrame {

    static final int WIDTH = 760;
    static final int HEIGHT = 420;
    static final int LEFT = 70;
    static final int RIGHT = 170;  // room for a legend
    static final int TOP = 40;
    static final int BOTTOM = 60;
    static final String AXIS = "#333333";
    static final String GRID = "#dddddd";

    private final SvgDocument svg = new SvgDocument(WIDTH, HEIGHT);
    private final Ticks x;
    private final Ticks y;

    PlotFrame(String title, String xLabel, String yLabel, Ticks x, Ticks y) {
        this.x = x;
        this.y = y;
        rect(0, 0, WIDTH, HEIGHT, "#ffffff", null);
        text(WIDTH / 2.0, TOP / 2.0 + 5, "middle", 16, title, false);
        for (double v : y.values()) {
            line(LEFT, py(v), LEFT + plotWidth(), py(v), GRID, 1);
            text(LEFT - 6, py(v) + 4, "end", 11, y.label(v), false);
        }
        if (x != null) {
            for (double v : x.values()) {
                line(px(v), TOP + plotHeight(), px(v), TOP + plotHeight() + 5, AXIS, 1);
                text(px(v), TOP + plotHeight() + 18, "middle", 11, x.label(v), false);
            }
        }
        line(LEFT, TOP, LEFT, TOP + plotHeight(), AXIS, 1);
        line(LEFT, TOP + plotHeight(), LEFT + plotWidth(), TOP + plotHeight(), AXIS, 1);
        text(LEFT + plotWidth() / 2.0, HEIGHT - 15, "middle", 12, xLabel, false);
        text(18, TOP + plotHeight() / 2.0, "middle", 12, yLabel, true);
    }

    static double plotWidth() {
        return WIDTH - LEFT - RIGHT;
    }

    static double plotHeight() {
        return HEIGHT - TOP - BOTTOM;
    }

    /** The pixel column of an x value (numeric axis) or of a position in [0, 1] (categorical axis). */
    double px(double value) {
        double f = x == null ? value : (value - x.min()) / (x.max() - x.min());
        return LEFT + f * plotWidth();
    }

    /** The pixel row of a y value. */
    double py(double value) {
        return TOP + plotHeight() - (value - y.min()) / (y.max() - y.min()) * plotHeight();
    }

    /** One legend entry, {@code row} from the top. */
    void legend(int row, String colour, String label) {
        double lx = LEFT + plotWidth() + 15;
        double ly = TOP + 10 + row * 18;
        rect(lx, ly - 9, 12, 10, colour, null);
        text(lx + 18, ly, "start", 11, label, false);
    }

    void line(double x1, double y1, double x2, double y2, String stroke, double strokeWidth) {
        svg.element("line").attr("x1", x1).attr("y1", y1).attr("x2", x2).attr("y2", y2).attr("stroke", stroke)
                .attr("stroke-width", strokeWidth).end();
    }

    /** A polyline through {@code points}, each an {x, y} pair; {@code title} (may be null) shows on hover. */
    void polyline(List<double[]> points, String stroke, String title) {
        StringBuilder p = new StringBuilder();
        for (double[] xy : points) {
            p.append(p.isEmpty() ? "" : " ").append(SvgDocument.number(xy[0])).append(',')
                    .append(SvgDocument.number(xy[1]));
        }
        svg.element("polyline").attr("fill", "none").attr("stroke", stroke).attr("stroke-width", 1.5)
                .attr("points", p.toString()).title(title);
    }

    void rect(double x, double y, double w, double h, String fill, String title) {
        svg.element("rect").attr("x", x).attr("y", y).attr("width", w).attr("height", h).attr("fill", fill)
                .title(title);
    }

    void circle(double cx, double cy, double r, String fill, String title) {
        svg.element("circle").attr("cx", cx).attr("cy", cy).attr("r", r).attr("fill", fill).title(title);
    }

    /** Text at (x, y), anchored {@code start}, {@code middle} or {@code end}; {@code rotate} turns it -90°. */
    void text(double x, double y, String anchor, int size, String content, boolean rotate) {
        SvgDocument.Element text = svg.element("text").attr("x", x).attr("y", y).attr("text-anchor", anchor)
                .attr("font-family", "sans-serif").attr("font-size", size);
        if (rotate) {
            text.attr("transform", "rotate(-90 " + SvgDocument.number(x) + " " + SvgDocument.number(y) + ")");
        }
        text.text(content);
    }

    /** The whole plot. */
    String render() {
        return svg.render();
    }
}
