package org.habla.security;

import static java.nio.charset.StandardCharsets.US_ASCII;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.KeyStore;
import java.security.PrivateKey;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.security.spec.PKCS8EncodedKeySpec;
import java.util.Base64;
import java.util.Collection;
import java.util.List;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;
import javax.net.ssl.TrustManagerFactory;

/**
 * TLS with the JDK's own implementation, from the PEM files a lab makes with {@code openssl} (see
 * {@code docs/security.md}): a server side from a certificate and its unencrypted PKCS#8 key, a client side that
 * trusts one certificate (the lab's, or the CA that signed it). TLS 1.3 and 1.2 only.
 *
 * <p>A server upgrades each accepted connection itself ({@link #upgrade}) on the connection's own thread: a TLS
 * client speaks first, so a peer whose first byte is not a TLS handshake record, or that says nothing within
 * {@link #FIRST_BYTE_MS}, is a plain client: it gets one plain error line saying so, and is closed, instead of
 * waiting for a hello that never comes.
 */
public final class Tls {

    /** How long a new connection may take to send its first byte before it is taken for a plain client. */
    public static final int FIRST_BYTE_MS = 2_000;
    /** How long a TLS handshake may take. */
    public static final int HANDSHAKE_MS = 10_000;
    /** The first byte of every TLS record that starts a handshake. */
    private static final int HANDSHAKE_RECORD = 0x16;
    private static final String[] PROTOCOLS = {"TLSv1.3", "TLSv1.2"};

    private final SSLContext context;

    private Tls(SSLContext context) {
        this.context = context;
    }

    /** The server side: {@code certificate} (PEM, the chain) and {@code key} (PEM, unencrypted PKCS#8). */
    public static Tls server(Path certificate, Path key) throws IOException {
        try {
            List<Certificate> chain = certificates(certificate);
            PrivateKey privateKey = privateKey(key);
            KeyStore store = KeyStore.getInstance("PKCS12");
            store.load(null, null);
            char[] none = new char[0];
            store.setKeyEntry("habla", privateKey, none, chain.toArray(Certificate[]::new));
            KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            kmf.init(store, none);
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(kmf.getKeyManagers(), null, null);
            return new Tls(ctx);
        } catch (GeneralSecurityException e) {
            throw new IOException("TLS cannot use " + certificate + " and " + key + ": " + e.getMessage(), e);
        }
    }

    /** The client side, trusting the certificates in {@code trusted} (PEM) and no other. */
    public static Tls client(Path trusted) throws IOException {
        try {
            KeyStore store = KeyStore.getInstance("PKCS12");
            store.load(null, null);
            int i = 0;
            for (Certificate c : certificates(trusted)) {
                store.setCertificateEntry("trusted-" + i++, c);
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(store);
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(null, tmf.getTrustManagers(), null);
            return new Tls(ctx);
        } catch (GeneralSecurityException e) {
            throw new IOException("TLS cannot trust " + trusted + ": " + e.getMessage(), e);
        }
    }

    /** What a plain client told {@link #upgrade} it is not speaking TLS. */
    public static final class PlainClient extends IOException {
        PlainClient(String message) {
            super(message);
        }
    }

    /**
     * Turns an accepted connection into the server side of a TLS connection, handshake done.
     *
     * @param plainError the line a plain client gets before it is closed
     * @throws PlainClient when the peer is not speaking TLS (it has had {@code plainError}; the socket is closed)
     * @throws IOException when the handshake fails (the socket is closed)
     */
    public SSLSocket upgrade(Socket accepted, byte[] plainError) throws IOException {
        try {
            accepted.setSoTimeout(FIRST_BYTE_MS);
            InputStream in = accepted.getInputStream();
            int first;
            try {
                first = in.read();
            } catch (SocketTimeoutException e) {
                first = -2;
            }
            if (first != HANDSHAKE_RECORD) {
                if (first != -1) {
                    accepted.getOutputStream().write(plainError);
                    accepted.getOutputStream().flush();
                }
                accepted.close();
                throw new PlainClient(first == -2 ? "said nothing within " + FIRST_BYTE_MS + " ms: a plain client"
                        : first == -1 ? "closed before a handshake" : "sent plain text, not a TLS handshake");
            }
            SSLSocket s = (SSLSocket) context.getSocketFactory().createSocket(accepted,
                    new ByteArrayInputStream(new byte[] {(byte) first}), true);
            s.setUseClientMode(false);
            s.setEnabledProtocols(PROTOCOLS);
            s.setSoTimeout(HANDSHAKE_MS);
            s.startHandshake();
            s.setSoTimeout(0);
            return s;
        } catch (IOException e) {
            closeQuietly(accepted);
            throw e;
        }
    }

    /** The client side of a TLS connection over {@code connected}, handshake done and the host name checked. */
    public SSLSocket connect(Socket connected, String host, int port, int timeoutMs) throws IOException {
        SSLSocket s = (SSLSocket) context.getSocketFactory().createSocket(connected, host, port, true);
        s.setUseClientMode(true);
        s.setEnabledProtocols(PROTOCOLS);
        var params = s.getSSLParameters();
        params.setEndpointIdentificationAlgorithm("HTTPS");
        s.setSSLParameters(params);
        s.setSoTimeout(timeoutMs);
        s.startHandshake();
        return s;
    }

    private static List<Certificate> certificates(Path file) throws IOException, GeneralSecurityException {
        try (InputStream in = Files.newInputStream(file)) {
            Collection<? extends Certificate> all = CertificateFactory.getInstance("X.509").generateCertificates(in);
            if (all.isEmpty()) {
                throw new GeneralSecurityException(file + " holds no certificate");
            }
            return List.copyOf(all);
        }
    }

    private static PrivateKey privateKey(Path file) throws IOException, GeneralSecurityException {
        String pem = Files.readString(file, US_ASCII);
        String begin = "-----BEGIN PRIVATE KEY-----";
        int a = pem.indexOf(begin);
        int b = pem.indexOf("-----END PRIVATE KEY-----");
        if (a < 0 || b < a) {
            throw new GeneralSecurityException(file + " holds no unencrypted PKCS#8 key (\"" + begin + "\"); convert "
                    + "one with: openssl pkcs8 -topk8 -nocrypt -in OLD -out " + file);
        }
        byte[] der = Base64.getMimeDecoder().decode(pem.substring(a + begin.length(), b));
        GeneralSecurityException last = null;
        for (String algorithm : List.of("RSA", "EC", "Ed25519", "Ed448")) {
            try {
                return KeyFactory.getInstance(algorithm).generatePrivate(new PKCS8EncodedKeySpec(der));
            } catch (GeneralSecurityException e) {
                last = e;
            }
        }
        throw new GeneralSecurityException(file + ": not an RSA, EC or EdDSA key", last);
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            // nothing more to do
        }
    }
}
