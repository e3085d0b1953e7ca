package org.habla.methods.speech;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Where the Moonshine model lives and whether it is whole. The files are never in the repository:
 * {@code ./habla models fetch} extracts them from their PyPI wheels, makes the ONNX models HABLA runs from them
 * ({@code .mvn/moonshine_convert.py}) and puts them into a cache folder outside it,
 * {@code $HABLA_MODELS/moonshine-base-en} (default {@code ~/.cache/habla/models/moonshine-base-en}), and
 * checks them against the SHA-256 sums pinned beside this class ({@code moonshine-base-en.sha256}). A lab
 * without a network copies that folder from a machine that fetched it.
 */
public final class MoonshineFiles {

    /** The folder's name in the cache. */
    public static final String MODEL = "moonshine-base-en";
    /** The command that fetches the model. */
    public static final String FETCH = "./habla models fetch";
    private static final String SUMS = "/org/habla/methods/speech/moonshine-base-en.sha256";

    private MoonshineFiles() {
    }

    /** The default model folder: {@code $HABLA_MODELS}, else {@code $XDG_CACHE_HOME/habla/models}, else {@code ~/.cache/habla/models}. */
    public static Path defaultFolder() {
        String models = System.getenv("HABLA_MODELS");
        if (models != null && !models.isBlank()) {
            return Path.of(models).resolve(MODEL);
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path cache = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return cache.resolve("habla").resolve("models").resolve(MODEL);
    }

    /** The pinned sums: file name → SHA-256 in hex. */
    static Map<String, String> pinned() {
        try (InputStream in = MoonshineFiles.class.getResourceAsStream(SUMS)) {
            if (in == null) {
                throw new IllegalStateException(SUMS + " is missing from the class path");
            }
            Map<String, String> sums = new LinkedHashMap<>();
            for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
                if (!line.isBlank() && !line.startsWith("#")) {
                    String[] f = line.trim().split("\\s+", 2);
                    sums.put(f[1], f[0]);
                }
            }
            return sums;
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + SUMS, e);
        }
    }

    /** What is missing from {@code folder}, as a sentence naming the command that fetches it; empty when nothing is. */
    public static String missing(Path folder) {
        List<String> absent = pinned().keySet().stream().filter(f -> !Files.isRegularFile(folder.resolve(f))).toList();
        if (absent.isEmpty()) {
            return "";
        }
        return "the Moonshine model is missing from " + folder + " (" + String.join(", ", absent) + "): fetch it with "
                + FETCH + ", or copy the folder " + MODEL + " from a machine that has it";
    }

    /** Checks every file of {@code folder} against its pinned sum; an IOException names the first that differs. */
    static void verify(Path folder) throws IOException {
        String missing = missing(folder);
        if (!missing.isEmpty()) {
            throw new IOException(missing);
        }
        for (Map.Entry<String, String> e : pinned().entrySet()) {
            String sum = sha256(folder.resolve(e.getKey()));
            if (!sum.equals(e.getValue())) {
                throw new IOException(folder.resolve(e.getKey()) + " is not the pinned file (SHA-256 " + sum + ", pinned "
                        + e.getValue() + "): fetch the model again with " + FETCH);
            }
        }
    }

    static String sha256(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            byte[] buf = new byte[1 << 16];
            for (int n = in.read(buf); n > 0; n = in.read(buf)) {
                d.update(buf, 0, n);
            }
            return HexFormat.of().formatHex(d.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
