package org.habla.sim.world;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * A simulated world as a world file describes it: the arena's walls as segments, the target object as a disc,
 * where the robot starts and how the teacher behaves. Immutable; the target's current place during a run lives
 * in {@link Scene}. Answers the two geometric questions the simulated sensors and the body ask: how far a ray
 * travels ({@link #rangeAlong}) and how much room there is around a point ({@link #clearance}).
 */
public record World(String name, List<Segment> walls, Target target, Pose2 robotStart, TeacherSettings teacher) {

    public World {
        Objects.requireNonNull(name, "name");
        walls = List.copyOf(walls);
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(robotStart, "robotStart");
        Objects.requireNonNull(teacher, "teacher");
    }

    /** Reads a world file. */
    public static World load(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            return WorldReader.read(in, file.toString());
        }
    }

    /** A world file if {@code name} is one, else the built-in world of that name (with or without {@code .json}). */
    public static World named(String name) throws IOException {
        Path file = Path.of(name);
        if (Files.isRegularFile(file)) {
            return load(file);
        }
        try {
            return builtIn(name.endsWith(".json") ? name.substring(0, name.length() - 5) : name);
        } catch (IllegalArgumentException e) {
            throw new IOException("'" + name + "' is neither a world file nor a built-in world (pioneer-room, "
                    + "pioneer-hall, aibo-arena)");
        }
    }

    /** Reads one of the world files shipped with HABLA, e.g. {@code pioneer-room} or {@code aibo-arena}. */
    public static World builtIn(String name) {
        String resource = "/worlds/" + name + ".json";
        try (InputStream in = World.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalArgumentException("no built-in world named '" + name + "'");
            }
            return WorldReader.read(in, resource);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * How far a ray from ({@code x}, {@code y}) heading {@code angleRad} (world frame) travels before it meets a
     * wall or the target, capped at {@code maxRangeM}. Uses this world's own target.
     */
    public double rangeAlong(double x, double y, double angleRad, double maxRangeM) {
        return rangeAlong(x, y, angleRad, maxRangeM, target);
    }

    /** {@link #rangeAlong(double, double, double, double)} with the target where it is now. */
    public double rangeAlong(double x, double y, double angleRad, double maxRangeM, Target where) {
        double dx = Math.cos(angleRad);
        double dy = Math.sin(angleRad);
        double best = where.rayDistance(x, y, dx, dy);
        for (Segment wall : walls) {
            best = Math.min(best, wall.rayDistance(x, y, dx, dy));
        }
        return Math.min(best, maxRangeM);
    }

    /** Distance from ({@code x}, {@code y}) to the nearest wall or the target's edge; negative inside the target. */
    public double clearance(double x, double y, Target where) {
        double best = where.surfaceDistance(x, y);
        for (Segment wall : walls) {
            best = Math.min(best, wall.distanceTo(x, y));
        }
        return best;
    }

    /** The world-frame direction from ({@code x}, {@code y}) towards the nearest obstacle point, radians. */
    public double directionToNearest(double x, double y, Target where) {
        double best = where.surfaceDistance(x, y);
        double dir = Math.atan2(where.yM() - y, where.xM() - x);
        for (Segment wall : walls) {
            double[] p = wall.closestPoint(x, y);
            double d = Math.hypot(p[0] - x, p[1] - y);
            if (d < best) {
                best = d;
                dir = Math.atan2(p[1] - y, p[0] - x);
            }
        }
        return dir;
    }

    /** Whether a round robot of {@code radiusM} centred at ({@code x}, {@code y}) touches a wall or the target. */
    public boolean collides(double x, double y, double radiusM, Target where) {
        return clearance(x, y, where) < radiusM;
    }
}
