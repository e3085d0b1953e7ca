package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.habla.method.ControlNotice;
import org.habla.method.Output;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A control socket's listener on the engine ({@link ControlServer}): encodes each sample once and hands the same
 * bytes to every client's outbox, starting one client further along each time ({@link DeliveryRing}).
 */
final class ControlFanout implements ControlPoint.Listener {

    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);

    private final String socketName;
    private final List<ControlClient> clients;
    private final DeliveryRing ring = new DeliveryRing();

    /** @param clients the socket's clients as they come and go (read on every sample, never copied) */
    ControlFanout(String socketName, List<ControlClient> clients) {
        this.socketName = socketName;
        this.clients = clients;
    }

    @Override
    public void onSample(Output<?> output, Sample sample) {
        if (clients.isEmpty()) {
            return;
        }
        EncodedFrame frame;
        try {
            frame = EncodedFrame.sample(output.name(), sample);
        } catch (RuntimeException e) {
            LOG.warn("control socket '{}': cannot encode a sample of {}: {}", socketName, output, e.toString());
            return;
        }
        String name = output.name();
        ring.forEach(clients, c -> c.offerSample(name, frame));
    }

    @Override
    public void onNotice(ControlNotice notice) {
        ObjectNode line = JsonNodeFactory.instance.objectNode()
                .put("type", "notice")
                .put("notice", notice.notice())
                .put("method", notice.methodId())
                .put("t", notice.sourceMicros())
                .put("message", notice.message());
        line.set("detail", notice.detail().json());
        toAll(Frame.of(line));
    }

    @Override
    public void onControl(Frame line) {
        toAll(line);
    }

    @Override
    public void onStale(boolean stale, String why) {
        toAll(Frame.of(JsonNodeFactory.instance.objectNode()
                .put("type", "stale").put("stale", stale).put("why", why == null ? "" : why)));
    }

    private void toAll(Frame notice) {
        if (clients.isEmpty()) {
            return;
        }
        EncodedFrame encoded = EncodedFrame.of(notice);
        ring.forEach(clients, c -> c.offerNotice(encoded));
    }
}
