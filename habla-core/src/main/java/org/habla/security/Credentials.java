package org.habla.security;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The named clients a daemon admits, each with its token and its roles, and the secret it shares with its
 * workers: what a credentials file holds ({@link CredentialsFile}). Never printed: {@link #toString} names the
 * clients only.
 *
 * <p>A token is checked in constant time whatever the name: a client name that does not exist costs what a wrong
 * token costs, so timing tells a prober neither which names exist nor how much of a token was right.
 */
public final class Credentials {

    /** A client of the file: its name, the digest of its token, its roles. */
    record Client(String name, byte[] tokenDigest, Map<String, Role> roles) {
    }

    private static final byte[] NO_CLIENT = digest("no such client: a digest nothing matches");

    private final Map<String, Client> clients = new LinkedHashMap<>();
    private final byte[] workerSecret;
    private final Map<String, java.util.Set<String>> bridgeCommands;

    Credentials(List<Client> clients, byte[] workerSecret, Map<String, java.util.Set<String>> bridgeCommands) {
        clients.forEach(c -> this.clients.put(c.name(), c));
        this.workerSecret = workerSecret == null ? null : workerSecret.clone();
        this.bridgeCommands = Map.copyOf(bridgeCommands);
    }

    /** Credentials with these clients ({@code name -> token, roles}) and worker secret (may be null); for tests. */
    public static Credentials of(Map<String, Map.Entry<String, Map<String, Role>>> clients, String workerSecret) {
        return new Credentials(clients.entrySet().stream()
                .map(e -> new Client(e.getKey(), digest(e.getValue().getKey()), Map.copyOf(e.getValue().getValue())))
                .toList(), workerSecret == null ? null : workerSecret.getBytes(UTF_8), Map.of());
    }

    /** The client {@code name} if {@code token} is its token. */
    public Optional<Principal> verify(String name, String token) {
        Client c = name == null ? null : clients.get(name);
        byte[] expected = c == null ? NO_CLIENT : c.tokenDigest();
        boolean match = MessageDigest.isEqual(expected, digest(token == null ? "" : token));
        return match && c != null ? Optional.of(new Principal(c.name(), c.roles())) : Optional.empty();
    }

    /** The secret the daemon and its workers prove to each other, if the file has one. */
    public Optional<WorkerSecret> workerSecret() {
        return workerSecret == null ? Optional.empty() : Optional.of(new WorkerSecret(workerSecret));
    }

    /** The sockets the bridge {@code id} may write actions to (none when the file does not name it). */
    public java.util.Set<String> bridgeCommands(String id) {
        return bridgeCommands.getOrDefault(id, java.util.Set.of());
    }

    public List<String> clientNames() {
        return List.copyOf(clients.keySet());
    }

    @Override
    public String toString() {
        return "Credentials" + clients.keySet() + (workerSecret == null ? "" : " and a worker secret");
    }

    static byte[] digest(String token) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(token.getBytes(UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JDK has SHA-256", e);
        }
    }
}
