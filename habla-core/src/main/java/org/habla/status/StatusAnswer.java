package org.habla.status;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.time.Instant;
import java.util.function.Supplier;
import org.habla.net.Limits;
import org.habla.net.ClientId;
import org.habla.net.ConnectionGuard;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.security.AuditEntry;
import org.habla.security.AuditLog;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Principal;
import org.habla.security.Tls;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One status client's answer: the snapshot line — after the client has authenticated, where the endpoint requires
 * it — taken within the frame deadline or abandoned ({@link StatusServer}'s {@link ConnectionGuard} watches it).
 */
final class StatusAnswer implements ConnectionGuard.Guarded {

    private static final Logger LOG = LoggerFactory.getLogger(StatusServer.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    private volatile Socket socket;
    private final Supplier<ObjectNode> snapshot;
    private final ConnectionGuard guard;
    private final Limits limits;
    private final PortAccess access;
    private final AuditLog audit;
    private final Tls tls;
    private final ClientId id;
    private final long connected = System.nanoTime();
    private volatile boolean written;

    /** @param security who may read the endpoint, where refusals are audited, its TLS (null for plain TCP) */
    StatusAnswer(Socket socket, Supplier<ObjectNode> snapshot, ConnectionGuard guard, Limits limits,
            PortSecurity security) {
        this.socket = socket;
        this.snapshot = snapshot;
        this.guard = guard;
        this.limits = limits;
        this.access = security.access();
        this.audit = security.audit();
        this.tls = security.tls();
        this.id = new ClientId(Principal.STATUS, socket.getInetAddress().getHostAddress() + ":" + socket.getPort());
    }

    void run() {
        if (tls != null) {
            try {
                socket = tls.upgrade(socket, (JSON.createObjectNode().put("type", "error")
                        .put("code", "tls_required").put("message", "the status endpoint speaks TLS only: "
                                + "habla status --tls-trust CERT, or openssl s_client; see docs/security.md")
                        + "\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
            } catch (IOException e) {
                LOG.debug("status client: {}", e.getMessage());
                guard.left(this);
                return;
            }
        }
        try (Socket socket = this.socket) {
            if (access.required() && !authenticated()) {
                return;
            }
            byte[] line;
            try {
                line = JSON.writeValueAsBytes(snapshot.get());
            } catch (RuntimeException e) {
                LOG.warn("the status snapshot failed", e);
                line = JSON.writeValueAsBytes(JSON.createObjectNode()
                        .put("type", "error").put("code", "snapshot_failed").put("message", e.toString()));
            }
            OutputStream out = socket.getOutputStream();
            out.write(line);
            out.write('\n');
            out.flush();
            written = true;
            socket.shutdownOutput();
        } catch (IOException e) {
            LOG.debug("status client {}: {}", socket.getRemoteSocketAddress(), e.toString());
        } finally {
            guard.left(this);
        }
    }

    /** Says authentication is required, reads the auth line and checks it; false when refused. */
    private boolean authenticated() throws IOException {
        OutputStream out = socket.getOutputStream();
        out.write(JSON.writeValueAsBytes(JSON.createObjectNode().put("type", "hello")
                .put("protocol", StatusServer.PROTOCOL).put("auth", "required")));
        out.write('\n');
        out.flush();
        socket.setSoTimeout((int) Math.min(Integer.MAX_VALUE, limits.frameTimeoutMs()));
        Frame request;
        try {
            request = new FrameReader(socket.getInputStream(), limits.maxLineBytes(), 0).read();
        } catch (FrameException e) {
            refuse(out, e.code(), e.getMessage(), false);
            return false;
        }
        if (request == null) {
            return false;
        }
        if (!request.header().path("op").asText().equals("auth")) {
            refuse(out, "auth_required", "the status endpoint requires authentication: send "
                    + "{\"op\":\"auth\",\"client\":NAME,\"token\":TOKEN} first", false);
            return false;
        }
        return switch (access.authenticate(request.header(), id.host())) {
            case PortAccess.Admitted a -> true;
            case PortAccess.Refused r -> {
                LOG.info("status client {}: refused: {}", socket.getRemoteSocketAddress(), r.message());
                audit.add(new AuditEntry(Instant.now(), r.client(), id.address(), Principal.STATUS, "auth", null, null,
                        false, r.code() + ": " + r.message()));
                refuse(out, r.code(), r.message(), r.delayed());
                yield false;
            }
        };
    }

    private void refuse(OutputStream out, String code, String message, boolean delay) throws IOException {
        if (delay) {
            try {
                Thread.sleep(PortAccess.FAILURE_DELAY_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        out.write(JSON.writeValueAsBytes(JSON.createObjectNode()
                .put("type", "error").put("code", code).put("message", message)));
        out.write('\n');
        out.flush();
        socket.shutdownOutput();
    }

    @Override
    public long connectedNanos() {
        return connected;
    }

    @Override
    public long lastActiveNanos() {
        return connected;
    }

    /** It can read nothing until it has authenticated (where it must) and its answer is sent within the frame deadline. */
    @Override
    public long idleSinceNanos() {
        return connected;
    }

    @Override
    public ClientId id() {
        return id;
    }

    @Override
    public long frameSinceNanos() {
        return written ? 0 : connected;
    }

    /** An answer cannot be interrupted by an error line: the connection is closed. */
    @Override
    public void evict(String code, String message) {
        LOG.debug("status client {}: closed: {} {}", socket.getRemoteSocketAddress(), code, message);
        try {
            socket.close();
        } catch (IOException e) {
            LOG.debug("status client: close: {}", e.toString());
        }
    }
}
