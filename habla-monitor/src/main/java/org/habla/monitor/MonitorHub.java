package org.habla.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.habla.daemon.LiveGraph;
import org.habla.graph.OutputInfo;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The monitor's one thread ({@code habla-monitor}): it reads the daemon's status a few times a second and the
 * kept samples of the methods a page looks at, and offers each page its updates. It never runs on, waits for or
 * locks out an engine thread: the engine only drops sample references into {@link OutputHistory}.
 */
final class MonitorHub implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(MonitorHub.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** How often pages get the status (method states, rates, links, the watchdog, sockets). */
    static final long STATUS_PERIOD_MS = 250;
    /** How often a page gets the new values of the method it looks at. */
    static final long DETAIL_PERIOD_MS = 100;

    private final LiveGraph graph;
    private final OutputHistory history;
    private final Function<String, ViewedMethod> methodView;
    private final Map<Viewer, ViewedMethod> viewers = new ConcurrentHashMap<>();
    /** The last latency figures seen per method, kept through intervals in which it handled nothing. */
    private final Map<String, JsonNode> lastLatency = new HashMap<>();
    private final ScheduledExecutorService thread;
    private final AutoCloseable watch;
    private volatile String statusText = "{}";

    /**
     * @param methodView makes what a page is shown of a method, by id (null for an unknown id)
     */
    MonitorHub(LiveGraph graph, Function<String, ViewedMethod> methodView) {
        this.graph = graph;
        this.methodView = methodView;
        this.history = new OutputHistory(graph.outputs().stream().map(OutputInfo::producer).toList());
        this.watch = graph.watchOutputs(history::offer);
        this.thread = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "habla-monitor");
            t.setDaemon(true);
            return t;
        });
        thread.scheduleWithFixedDelay(guarded(this::sendStatus), 0, STATUS_PERIOD_MS, TimeUnit.MILLISECONDS);
        thread.scheduleWithFixedDelay(guarded(this::sendDetails), DETAIL_PERIOD_MS, DETAIL_PERIOD_MS,
                TimeUnit.MILLISECONDS);
    }

    OutputHistory history() {
        return history;
    }

    /** The newest status, as JSON text (read by {@code /status.json}; never asks the engine itself). */
    String statusText() {
        return statusText;
    }

    void join(Viewer v) {
        viewers.put(v, NO_METHOD);
        thread.execute(guarded(() -> v.offer(statusText)));
    }

    void leave(Viewer v) {
        viewers.remove(v);
    }

    int viewerCount() {
        return viewers.size();
    }

    /** Runs a task on the monitor's thread (a newly connected client's first messages). */
    void execute(Runnable task) {
        thread.execute(guarded(task::run));
    }

    /** Runs a task on the monitor's thread every {@code periodMs}. */
    void every(long periodMs, Runnable task) {
        thread.scheduleWithFixedDelay(guarded(task::run), periodMs, periodMs, TimeUnit.MILLISECONDS);
    }

    private void sendStatus() throws Exception {
        ObjectNode st = graph.status();
        for (JsonNode m : st.path("methods")) {
            String id = m.path("id").asText();
            if (m.path("latency").path("count").asLong() > 0) {
                lastLatency.put(id, m.get("latency"));
            } else if (lastLatency.containsKey(id)) {
                ((ObjectNode) m).set("latency", lastLatency.get(id).deepCopy());
                ((ObjectNode) m.get("latency")).put("count", 0);
            }
        }
        ObjectNode msg = JSON.createObjectNode().put("type", "status").put("atMicros", System.currentTimeMillis() * 1000);
        msg.set("status", st);
        statusText = JSON.writeValueAsString(msg);
        for (Viewer v : viewers.keySet()) {
            v.offer(statusText);
        }
    }

    private void sendDetails() throws Exception {
        long now = System.currentTimeMillis() * 1000;
        for (Map.Entry<Viewer, ViewedMethod> e : viewers.entrySet()) {
            Viewer v = e.getKey();
            ViewedMethod view = e.getValue();
            String selected = v.selected();
            if (selected == null) {
                continue;
            }
            if (view == NO_METHOD || !view.methodId().equals(selected)) {
                ViewedMethod fresh = methodView.apply(selected);
                if (fresh == null) {
                    continue;
                }
                view = fresh;
                viewers.replace(v, fresh);
            }
            // Built only when the page can take it: a busy page's view keeps its cursors, so it catches up later.
            if (!v.busy()) {
                v.offer(JSON.writeValueAsString(view.update(history, now)));
            }
        }
    }

    private static Runnable guarded(ThrowingRunnable r) {
        return () -> {
            try {
                r.run();
            } catch (Exception e) {
                LOG.warn("monitor: {}", e.toString());
            }
        };
    }

    @FunctionalInterface
    interface ThrowingRunnable {
        void run() throws Exception;
    }

    @Override
    public void close() {
        thread.shutdownNow();
        try {
            watch.close();
        } catch (Exception e) {
            LOG.debug("monitor watch: {}", e.toString());
        }
    }

    private static final ViewedMethod NO_METHOD = new ViewedMethod("", List.of(), null);
}
