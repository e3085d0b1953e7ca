package org.habla.monitor;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

/**
 * The monitor page's files, read once from the class path: a fixed table, so nothing else can be asked for.
 * The charting library (uPlot, MIT licence) is vendored beside the page, so the page works offline.
 */
final class WebFiles {

    static final String UPLOT = "vendor/uplot-1.6.32/";

    record WebFile(String contentType, byte[] bytes) {
    }

    private static final Map<String, String> TYPES = Map.of(
            "index.html", "text/html; charset=utf-8",
            "monitor.js", "text/javascript; charset=utf-8",
            "monitor.css", "text/css; charset=utf-8",
            UPLOT + "uPlot.iife.min.js", "text/javascript; charset=utf-8",
            UPLOT + "uPlot.min.css", "text/css; charset=utf-8",
            UPLOT + "LICENSE", "text/plain; charset=utf-8");

    private final Map<String, WebFile> files = new HashMap<>();

    WebFiles() {
        for (Map.Entry<String, String> e : TYPES.entrySet()) {
            String resource = "web/" + e.getKey();
            try (InputStream in = WebFiles.class.getResourceAsStream(resource)) {
                if (in == null) {
                    throw new IllegalStateException("the monitor's file " + resource + " is missing from the class path");
                }
                files.put("/" + e.getKey(), new WebFile(e.getValue(), in.readAllBytes()));
            } catch (IOException ex) {
                throw new UncheckedIOException(ex);
            }
        }
        files.put("/", files.get("/index.html"));
    }

    /** The file at a request path, or null. */
    WebFile get(String path) {
        return files.get(path);
    }
}
