package org.habla.testing;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * A lab certificate and its key, made by {@code openssl} as docs/security.md says: self-signed, for
 * {@code localhost} and {@code 127.0.0.1}, valid two days.
 *
 * @param certificate the certificate (PEM)
 * @param key         its private key (PEM)
 */
public record LabCertificate(Path certificate, Path key) {

    private static final long OPENSSL_SECONDS = 60;

    /** Makes {@code NAME.crt} and {@code NAME.key} in {@code dir}. */
    public static LabCertificate make(Path dir, String name) throws IOException, InterruptedException {
        Path certificate = dir.resolve(name + ".crt");
        Path key = dir.resolve(name + ".key");
        Process p = new ProcessBuilder("openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key.toString(), "-out", certificate.toString(),
                "-days", "2", "-subj", "/CN=localhost", "-addext", "subjectAltName=IP:127.0.0.1,DNS:localhost")
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(OPENSSL_SECONDS, TimeUnit.SECONDS) && p.exitValue() == 0).as("openssl: %s", out).isTrue();
        return new LabCertificate(certificate, key);
    }
}
