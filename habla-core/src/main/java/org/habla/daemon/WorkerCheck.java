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
import org.habla.net.FrameReader;
import org.habla.net.WorkerProtocol;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Asks every worker a config places methods on what it can run, before the daemon starts: a worker that
 * answers but cannot run a method placed on it (an unknown type, another protocol version) makes the
 * config wrong for this set-up, so the daemon refuses to start. A worker that does not answer is only
 * reported: it may come up later, and until then its methods' outputs are stale (or run locally).
 */
final class WorkerCheck {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerCheck.class);

    private WorkerCheck() {
    }

    /** One sentence per method placed on a worker that cannot run it; empty when all is well. */
    static List<String> refusals(HablaConfig config, int timeoutMillis) {
        Map<String, WorkerProtocol.Hello> hellos = new HashMap<>();
        boolean anyPlaced = config.methods().stream().anyMatch(m -> m.host().isPresent());
        org.habla.security.WorkerLink link = anyPlaced ? config.security().workerLink()
                : org.habla.security.WorkerLink.PLAIN;
        List<String> refusals = new ArrayList<>();
        for (MethodConfig mc : config.methods()) {
            if (mc.host().isEmpty()) {
                continue;
            }
            String host = mc.host().get();
            WorkerProtocol.Hello hello = hellos.computeIfAbsent(host, h -> hello(h, link, timeoutMillis));
            if (hello == null) {
                LOG.warn("worker {} of method {} does not answer; its outputs are {} until it does", host, mc.id(),
                        mc.fallback() == org.habla.config.Fallback.LOCAL ? "computed in the daemon" : "stale");
                continue;
            }
            String refusal = hello.refusal(mc.type());
            if (refusal == null && hello.asksForSecret() && link.secret() == null) {
                refusal = "the worker requires the shared secret and the credentials file gives no \"workerSecret\"";
            } else if (refusal == null && !hello.asksForSecret() && link.secret() != null) {
                refusal = "the worker does not ask for the shared secret, so it cannot prove it is the trusted worker "
                        + "(start it with --secret-file)";
            }
            if (refusal != null) {
                refusals.add("method '" + mc.id() + "' is placed on worker " + host + ", but " + refusal);
            }
        }
        return refusals;
    }

    private static WorkerProtocol.Hello hello(String host, org.habla.security.WorkerLink link, int timeoutMillis) {
        InterfaceAddress a = InterfaceAddress.parse(host);
        try (Socket plain = new Socket()) {
            plain.connect(new InetSocketAddress(a.host(), a.port().orElseThrow()), timeoutMillis);
            plain.setSoTimeout(timeoutMillis);
            Socket s = link.secure(plain, a.host(), a.port().orElseThrow(), timeoutMillis);
            FrameReader reader = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 0);
            var frame = reader.read();
            return frame == null ? null : WorkerProtocol.Hello.of(frame);
        } catch (IOException | RuntimeException e) {
            LOG.debug("worker {}: {}", host, e.toString());
            return null;
        }
    }
}
