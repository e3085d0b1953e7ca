package org.habla.methods.virtual;

import java.time.Duration;
import java.util.Map;
import org.habla.driver.LinkReport;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The link-state method, type {@code link-state}: whether the robot is connected, for the control
 * architecture. Input {@code link} takes the record the engine publishes on every interface's {@code link}
 * channel ({@code {"up", "interface", "detail", "connections"}}, on every change and once a second), carried up
 * by a {@code channel} and a {@code pass-through} method. Output {@code link} is the record
 *
 * <pre>{@code {"connected": true, "stale": false, "sinceMs": 5300, "interface": "robot", "detail": "all connections up",
 *  "connections": {"arcos": true}}}</pre>
 *
 * where {@code sinceMs} is how long the link has been in its present state (as seen here) and {@code stale}
 * says the news is doubtful: the sample came marked stale, or no link record came for {@code staleAfterMs}.
 * It is emitted on every link record and when the records stop. {@code connections} is each of the driver's
 * connections and whether it is up (a robot with several servers may stream on some while another is down).
 */
public final class LinkState extends VirtualMethod {

    private static final InputPort<RecordValue> LINK_IN = InputPort.of("link", RecordValue.class, Delivery.latest());
    private static final OutputPort<RecordValue> LINK = OutputPort.of("link", RecordValue.class, Shape.record(
            "whether the robot's link is up, whether that news is stale, and for how long it has been so",
            LinkStatus.LAYOUT));
    static final Ports PORTS = Ports.of(LINK_IN, LINK);

    private final LinkStateParams params;
    private final Output<RecordValue> out = output(LINK);

    private boolean known;
    private boolean connected;
    private boolean staleSample;
    private boolean silent;
    private long changedMicros;
    private long lastRecordMicros;
    private String iface = "";
    private String detail = "";
    private Map<String, Boolean> connections = Map.of();
    private long malformed;

    LinkState(LinkStateParams params) {
        this.params = params;
        input(LINK_IN, this::onLink);
        tickEvery(Duration.ofMillis(Math.max(50, params.staleAfterMs() / 4)));
    }

    private void onLink(RecordValue value, Sample sample) {
        LinkReport report = LinkReport.fromRecord(value).orElse(null);
        if (report == null) {
            if (malformed++ == 0) {
                log().warn("{}: a link record without a boolean 'up' was ignored: {}", id(), value);
            }
            return;
        }
        long now = nowMicros();
        if (!known || report.up() != connected) {
            changedMicros = now;
        }
        known = true;
        connected = report.up();
        staleSample = sample.stale();
        silent = false;
        lastRecordMicros = now;
        iface = report.iface();
        detail = report.detail();
        connections = report.connections();
        publish(now);
    }

    @Override
    protected void onTick(long nowMicros) {
        if (known && !silent && nowMicros - lastRecordMicros > params.staleAfterMs() * 1000L) {
            silent = true;
            publish(nowMicros);
        }
    }

    private void publish(long now) {
        emit(out, RecordValue.of(new LinkStatus(connected, staleSample || silent, (now - changedMicros) / 1000, iface,
                silent ? "no link news for " + params.staleAfterMs() + " ms" : detail, connections)));
    }

    /** Records without a boolean {@code up}, since start. */
    public long malformed() {
        return malformed;
    }

    /** Makes {@code link-state} methods. */
    public static final class Provider extends SimpleMethodProvider<LinkStateParams> {
        public Provider() {
            super("link-state", "Whether the robot's link is up, whether that is stale, and since when",
                    LinkStateParams.class, PORTS, (layer, p) -> new LinkState(p), Layer.VIRTUAL);
        }
    }
}
