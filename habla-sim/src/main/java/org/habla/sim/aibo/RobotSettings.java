package org.habla.sim.aibo;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The Tekkotsu configuration values the simulated Aibo honours, changed at run time by the
 * Controller's {@code !set section.key=value}:
 *
 * <table>
 * <caption>settings</caption>
 * <tr><th>key</th><th>default</th><th>meaning</th></tr>
 * <tr><td>{@code main.worldState_interval}</td><td>0</td><td>ms between World State packets (0: every 32 ms update)</td></tr>
 * <tr><td>{@code vision.rawcam.y_skip}</td><td>2</td><td>raw camera resolution: 0 = 416×320 … 5 = 13×10</td></tr>
 * <tr><td>{@code vision.rawcam.uv_skip}</td><td>3</td><td>accepted; the JPEG's chroma is always subsampled 2×</td></tr>
 * <tr><td>{@code vision.rawcam.interval}</td><td>0</td><td>ms between camera frames (0: every frame, ~30 fps)</td></tr>
 * <tr><td>{@code vision.rawcam.transport}</td><td>TCP</td><td>only TCP is simulated (Tekkotsu's simulator default)</td></tr>
 * <tr><td>{@code vision.rawcam.compression}</td><td>jpeg</td><td>only jpeg is simulated</td></tr>
 * </table>
 * Old flat names ({@code vision.rawcam_interval}) map to the dotted ones. Other keys are stored and
 * otherwise ignored.
 */
final class RobotSettings {

    private final Map<String, String> values = new ConcurrentHashMap<>(Map.of(
            "main.worldState_interval", "0",
            "vision.rawcam.y_skip", "2",
            "vision.rawcam.uv_skip", "3",
            "vision.rawcam.interval", "0",
            "vision.rawcam.transport", "TCP",
            "vision.rawcam.compression", "jpeg"));

    /** Sets {@code key} to {@code value}; the reason it was refused, if it was. */
    Optional<String> set(String key, String value) {
        String k = key.strip().replace("rawcam_", "rawcam.");
        String v = value.strip();
        switch (k) {
            case "main.worldState_interval", "vision.rawcam.interval" -> {
                Optional<String> bad = integer(k, v, 0, 60_000);
                if (bad.isPresent()) {
                    return bad;
                }
            }
            case "vision.rawcam.y_skip", "vision.rawcam.uv_skip" -> {
                Optional<String> bad = integer(k, v, 0, 5);
                if (bad.isPresent()) {
                    return bad;
                }
            }
            case "vision.rawcam.transport" -> {
                if (!v.equalsIgnoreCase("TCP")) {
                    return Optional.of("the simulated Aibo serves the raw camera over TCP only");
                }
            }
            case "vision.rawcam.compression" -> {
                if (!v.equalsIgnoreCase("jpeg")) {
                    return Optional.of("the simulated Aibo sends JPEG frames only");
                }
            }
            default -> {
                // stored, not simulated
            }
        }
        values.put(k, v);
        return Optional.empty();
    }

    long worldStateIntervalMs() {
        return Long.parseLong(values.get("main.worldState_interval"));
    }

    int rawCamSkip() {
        return Integer.parseInt(values.get("vision.rawcam.y_skip"));
    }

    long rawCamIntervalMs() {
        return Long.parseLong(values.get("vision.rawcam.interval"));
    }

    private static Optional<String> integer(String key, String v, int min, int max) {
        try {
            int n = Integer.parseInt(v);
            if (n >= min && n <= max) {
                return Optional.empty();
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        return Optional.of(key + " takes a whole number in " + min + ".." + max + ", not '" + Abbreviation.of(v)
                + "'");
    }
}
