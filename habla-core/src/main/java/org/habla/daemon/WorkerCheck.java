package org.habla.daemon;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.driver.InterfaceAddress;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.WorkerProtocol;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Asks every worker a config places methods on what it can run, and proves the shared secret to it, before the
 * daemon starts: a worker that answers but cannot run a method placed on it (an unknown type, another protocol
 * version), or that does not trust this daemon's secret (or cannot prove its own), makes the config wrong for this
 * set-up, so the daemon refuses to start. A worker that does not answer is only reported: it may come up later, and
 * until then its methods' outputs are stale (or run locally). Once the daemon runs, a worker that refuses it later
 * (restarted with another secret) leaves its placement down, the reason in the status, and is tried again.
 */
final class WorkerCheck {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerCheck.class);

    private WorkerCheck() {
    }

    /** What a worker said: its hello, and why the two do not trust each other (null when they do). */
    private record Answer(WorkerProtocol.Hello hello, String distrust) {
    }

    /** One sentence per method placed on a worker that cannot run it; empty when all is well. */
    static List<String> refusals(HablaConfig config, int timeoutMillis) {
        Map<String, Answer> answers = new HashMap<>();
        boolean anyPlaced = config.methods().stream().anyMatch(m -> m.host().isPresent());
        org.habla.security.WorkerLink link = anyPlaced ? config.security().workerLink()
                : org.habla.security.WorkerLink.PLAIN;
        List<String> refusals = new ArrayList<>();
        for (MethodConfig mc : config.methods()) {
            if (mc.host().isEmpty()) {
                continue;
            }
            String host = mc.host().get();
            Answer answer = answers.computeIfAbsent(host, h -> ask(h, link, timeoutMillis));
            if (answer == null) {
                LOG.warn("worker {} of method {} does not answer; its outputs are {} until it does", host, mc.id(),
                        mc.fallback() == org.habla.config.Fallback.LOCAL ? "computed in the daemon" : "stale");
                continue;
            }
            String refusal = answer.hello().refusal(mc.type());
            if (refusal == null) {
                refusal = answer.distrust();
            }
            if (refusal != null) {
                refusals.add("method '" + mc.id() + "' is placed on worker " + host + ", but " + refusal);
            }
        }
        return refusals;
    }

    /**
     * Whether a failed proof is the two sides not trusting each other — the worker's {@code auth_failed}, or the
     * secret missing, unasked for or unproven on either side — rather than a worker that is busy or went away.
     */
    private static boolean distrust(String message) {
        return message != null && (message.contains("auth_failed") || message.contains("shared secret"));
    }

    /** Reads the worker's hello and, where it speaks this daemon's protocol, proves the secret; null if no answer. */
    private static Answer ask(String host, org.habla.security.WorkerLink link, int timeoutMillis) {
        InterfaceAddress a = InterfaceAddress.parse(host);
        try (Socket plain = new Socket()) {
            plain.connect(new InetSocketAddress(a.host(), a.port().orElseThrow()), timeoutMillis);
            plain.setSoTimeout(timeoutMillis);
            Socket s = link.secure(plain, a.host(), a.port().orElseThrow(), timeoutMillis);
            FrameReader reader = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 0);
            var frame = reader.read();
            if (frame == null) {
                return null;
            }
            WorkerProtocol.Hello hello = WorkerProtocol.Hello.of(frame);
            if (!WorkerProtocol.PROTOCOL.equals(hello.protocol())) {
                return new Answer(hello, null); // refused by type check, which names both versions
            }
            try {
                WorkerProtocol.prove(hello, link.secret(), reader, new FrameWriter(s.getOutputStream()), host);
                return new Answer(hello, null);
            } catch (FrameException | java.net.SocketException | java.io.InterruptedIOException e) {
                throw e; // the connection failed or went quiet: as if the worker had not answered
            } catch (IOException e) {
                if (distrust(e.getMessage())) {
                    return new Answer(hello, e.getMessage());
                }
                // Busy (too_many_methods) or gone mid-way: the placement tries again once the daemon runs.
                LOG.warn("worker {}: {}", host, e.getMessage());
                return new Answer(hello, null);
            }
        } catch (IOException | RuntimeException e) {
            LOG.debug("worker {}: {}", host, e.toString());
            return null;
        }
    }
}
