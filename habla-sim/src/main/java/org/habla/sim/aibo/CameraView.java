package org.habla.sim.aibo;

import java.util.List;

/**
 * What the Aibo's camera looks at, at one instant: the arena's walls (vertical, from the floor up to
 * {@code wallHeightM}), the ball resting on the floor, and where the camera is and points.
 *
 * @param walls       wall segments {@code [x1, y1, x2, y2]} in metres, world frame
 * @param wallHeightM the walls' height
 * @param ball        the ball
 * @param camera      the camera's pose
 */
public record CameraView(List<double[]> walls, double wallHeightM, Ball ball, CameraPose camera) {

    /** A ball of radius {@code radiusM} lying on the floor at ({@code xM}, {@code yM}), drawn in {@code rgb}. */
    public record Ball(double xM, double yM, double radiusM, int rgb) {
    }

    /**
     * The camera's optical centre and direction: {@code yawRad} counter-clockwise from the world's x axis,
     * {@code pitchRad} positive looking up.
     */
    public record CameraPose(double xM, double yM, double zM, double yawRad, double pitchRad) {
    }

    public CameraView {
        walls = List.copyOf(walls);
    }
}
