package org.habla.security;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Base64;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The secret a daemon and its workers share, and the challenge–response by which each proves it holds it without
 * sending it (HMAC-SHA256). Each side sends a fresh random challenge; each answers the pair of challenges with an
 * HMAC that names its own side, so an answer cannot be replayed on another connection nor reflected back.
 *
 * <pre>
 *   worker  hello {"auth":"required","challenge":Cw}
 *   daemon  {"type":"auth","challenge":Cd,"proof":HMAC(secret, "habla-worker/1 daemon Cw Cd")}
 *   worker  {"type":"trusted","proof":HMAC(secret, "habla-worker/1 worker Cw Cd")}   or error auth_failed, closed
 * </pre>
 *
 * Never printed: {@link #toString} says nothing of the secret.
 */
public final class WorkerSecret {

    /** Random bytes in each challenge. */
    public static final int CHALLENGE_BYTES = 32;
    /** The shortest secret accepted, in characters. */
    public static final int MIN_CHARS = CredentialsFile.MIN_SECRET_CHARS;

    private static final SecureRandom RANDOM = new SecureRandom();

    private final byte[] secret;

    WorkerSecret(byte[] secret) {
        this.secret = secret.clone();
    }

    /** A secret from its text; at least {@link #MIN_CHARS} characters. */
    public static WorkerSecret of(String text) {
        if (text == null || text.length() < MIN_CHARS) {
            throw new IllegalArgumentException("a worker secret needs at least " + MIN_CHARS + " characters");
        }
        return new WorkerSecret(text.getBytes(UTF_8));
    }

    /** A fresh challenge: {@link #CHALLENGE_BYTES} random bytes in base64. */
    public static String challenge() {
        byte[] b = new byte[CHALLENGE_BYTES];
        RANDOM.nextBytes(b);
        return Base64.getEncoder().encodeToString(b);
    }

    /** The proof {@code side} ({@code "daemon"} or {@code "worker"}) gives for the two challenges. */
    public String proof(String side, String workerChallenge, String daemonChallenge) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(secret, "HmacSHA256"));
            byte[] h = mac.doFinal(("habla-worker/1 " + side + " " + workerChallenge + " " + daemonChallenge)
                    .getBytes(UTF_8));
            return Base64.getEncoder().encodeToString(h);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("every JDK has HmacSHA256", e);
        }
    }

    /** Whether {@code proof} is what {@code side} holding this secret gives; in constant time. */
    public boolean verify(String proof, String side, String workerChallenge, String daemonChallenge) {
        if (proof == null || workerChallenge == null || daemonChallenge == null) {
            return false;
        }
        return MessageDigest.isEqual(proof.getBytes(UTF_8),
                proof(side, workerChallenge, daemonChallenge).getBytes(UTF_8));
    }

    @Override
    public String toString() {
        return "WorkerSecret[hidden]";
    }
}
