package org.habla.drivers.mqtt;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.util.Optional;
import javax.net.ssl.TrustManagerFactory;

/**
 * Reads what logging in to a broker needs from the files a config names: the password file and the certificate
 * authorities for TLS. Read at every connection, so a changed password or certificate is used on the next one.
 */
final class BrokerLogin {

    private BrokerLogin() {
    }

    /** The password given, or the first line of the password file, or empty. */
    static String password(String password, String passwordFile) throws IOException {
        if (passwordFile.isEmpty()) {
            return password;
        }
        try {
            String text = Files.readString(Path.of(passwordFile));
            int end = text.indexOf('\n');
            return (end < 0 ? text : text.substring(0, end)).strip();
        } catch (IOException e) {
            throw new IOException("cannot read the password file " + passwordFile + ": " + e.getMessage(), e);
        }
    }

    /** TLS settings for {@code tls} and {@code caFile}: empty without TLS. */
    static Optional<BrokerEndpoint.Tls> tls(boolean tls, String caFile) throws IOException {
        if (!tls) {
            return Optional.empty();
        }
        if (caFile.isEmpty()) {
            return Optional.of(new BrokerEndpoint.Tls(null));
        }
        try (InputStream in = Files.newInputStream(Path.of(caFile))) {
            KeyStore store = KeyStore.getInstance(KeyStore.getDefaultType());
            store.load(null, null);
            int n = 0;
            for (Certificate c : CertificateFactory.getInstance("X.509").generateCertificates(in)) {
                store.setCertificateEntry("ca-" + n++, c);
            }
            if (n == 0) {
                throw new IOException("the CA file " + caFile + " holds no certificate");
            }
            TrustManagerFactory f = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            f.init(store);
            return Optional.of(new BrokerEndpoint.Tls(f));
        } catch (GeneralSecurityException e) {
            throw new IOException("cannot read the CA file " + caFile + ": " + e.getMessage(), e);
        }
    }
}
