package org.habla.sim.scenario;

/**
 * The frame of a plot: title, axes, grid lines and tick labels around a plotting area, and the mapping of
 * data values to pixels. The x axis is either numeric (with {@link Ticks}) or categorical (no ticks: the
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

    final SvgDocument svg = new SvgDocument(WIDTH, HEIGHT);
    private final Ticks x;
    private final Ticks y;

    PlotFrame(String title, String xLabel, String yLabel, Ticks x, Ticks y) {
        this.x = x;
        this.y = y;
        svg.text(WIDTH / 2.0, TOP / 2.0 + 5, "middle", 16, title, false);
        for (double v : y.values()) {
            svg.line(LEFT, py(v), LEFT + plotWidth(), py(v), GRID, 1);
            svg.text(LEFT - 6, py(v) + 4, "end", 11, y.label(v), false);
        }
        if (x != null) {
            for (double v : x.values()) {
                svg.line(px(v), TOP + plotHeight(), px(v), TOP + plotHeight() + 5, AXIS, 1);
                svg.text(px(v), TOP + plotHeight() + 18, "middle", 11, x.label(v), false);
            }
        }
        svg.line(LEFT, TOP, LEFT, TOP + plotHeight(), AXIS, 1);
        svg.line(LEFT, TOP + plotHeight(), LEFT + plotWidth(), TOP + plotHeight(), AXIS, 1);
        svg.text(LEFT + plotWidth() / 2.0, HEIGHT - 15, "middle", 12, xLabel, false);
        svg.text(18, TOP + plotHeight() / 2.0, "middle", 12, yLabel, true);
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
        svg.rect(lx, ly - 9, 12, 10, colour, null);
        svg.text(lx + 18, ly, "start", 11, label, false);
    }
}
