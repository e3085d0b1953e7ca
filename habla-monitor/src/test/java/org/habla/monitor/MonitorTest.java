package org.habla.monitor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.habla.method.Shape;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(60)
class MonitorTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final HttpClient http = HttpClient.newHttpClient();
    private FakeGraph graph;
    private Monitor monitor;

    @BeforeEach
    void start() throws Exception {
        graph = new FakeGraph(FakeGraph.output("m", "ranges", Shape.vector("m", "ranges")),
                FakeGraph.output("m", "where", Shape.record("where", "distanceM", "seen")),
                FakeGraph.output("m", "image", Shape.of(org.habla.sample.PayloadKind.IMAGE)));
        monitor = Monitor.start("127.0.0.1", 0, graph, "<svg xmlns=\"http://www.w3.org/2000/svg\"/>");
    }

    @AfterEach
    void stop() {
        monitor.close();
    }

    @Test
    void thePageAndItsFilesAreServedAndNothingCanBeWritten() throws Exception {
        HttpResponse<String> page = get("/");
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.body()).contains("HABLA monitor").contains("uPlot.iife.min.js");
        assertThat(get("/vendor/uplot-1.6.32/uPlot.iife.min.js").statusCode()).isEqualTo(200);
        assertThat(get("/graph.svg").body()).startsWith("<svg");
        assertThat(get("/../pom.xml").statusCode()).isIn(400, 404);
        assertThat(get("/monitor.java").statusCode()).isEqualTo(404);
        HttpResponse<String> post = http.send(HttpRequest.newBuilder(uri("/live"))
                .POST(HttpRequest.BodyPublishers.ofString("{\"value\":\"forward\"}")).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(post.statusCode()).isEqualTo(405);
    }

    @Test
    void aPageGetsTheStatusAndTheNewValuesOfTheMethodItSelectsAndMayWriteNothingElse() throws Exception {
        Page page = new Page();
        page.await(m -> m.path("type").asText().equals("status")
                && m.at("/status/interfaces/0/id").asText().equals("robot"));
        page.socket.sendText("{\"select\":\"m\"}", true).join();
        JsonNode detail = null;
        for (int i = 0; detail == null && i < 200; i++) {
            graph.emit("m.ranges", VectorValue.of(0.5, 1.5, i));
            graph.emit("m.where", RecordValue.builder().put("distanceM", 2.5).put("seen", true).build());
            detail = page.poll(m -> m.path("type").asText().equals("detail")
                    && m.at("/outputs/m.ranges/points").size() > 0 && m.at("/outputs/m.where/points").size() > 0);
        }
        assertThat(detail).as("no detail with points came").isNotNull();
        assertThat(detail.at("/outputs/m.ranges/series").toString()).isEqualTo("[\"[0]\",\"[1]\",\"[2]\"]");
        assertThat(detail.at("/outputs/m.ranges/points/0/1").asDouble()).isEqualTo(0.5);
        assertThat(detail.at("/outputs/m.where/series").toString()).isEqualTo("[\"distanceM\"]");
        assertThat(detail.at("/outputs/m.where/last/seen").asBoolean()).isTrue();

        page.socket.sendText("{\"value\":\"forward\"}", true).join();
        page.await(m -> m.path("code").asText().equals("read_only"));
        page.socket.abort();
    }

    @Test
    void aPageThatStopsReadingCostsTheEngineNothingAndOtherPagesGoOn() throws Exception {
        Page stuck = new Page(false);
        stuck.socket.sendText("{\"select\":\"m\"}", true).join();
        Page live = new Page();
        live.socket.sendText("{\"select\":\"m\"}", true).join();
        byte[] jpeg = new byte[200_000];
        jpeg[0] = (byte) 0xff;
        // 20 000 frames of 200 kB offered by the "engine": far more than a socket's buffers take.
        for (int i = 0; i < 20_000; i++) {
            graph.emit("m.image", ImageFrame.wrap(320, 240, "jpeg", jpeg));
            graph.emit("m.ranges", VectorValue.of(i));
        }
        live.await(m -> m.at("/outputs/m.ranges/last/0").asInt() == 19_999);
        assertThat(stuck.received.size()).isLessThan(20);
        stuck.socket.abort();
        live.socket.abort();
    }

    @Test
    void pagesBeyondTheLimitAreRefused() throws Exception {
        for (int i = 0; i < Monitor.MAX_PAGES; i++) {
            new Page();
        }
        long deadline = System.currentTimeMillis() + 10_000;
        Throwable refused = null;
        while (refused == null && System.currentTimeMillis() < deadline) {
            try {
                new Page().socket.abort();
                Thread.sleep(50);   // a page may still have been counted as leaving
            } catch (Exception e) {
                refused = e;
            }
        }
        assertThat(refused).as("page number " + (Monitor.MAX_PAGES + 1)).isNotNull();
        assertThat(refused.getCause()).isInstanceOf(java.net.http.WebSocketHandshakeException.class);
        assertThat(((java.net.http.WebSocketHandshakeException) refused.getCause()).getResponse().statusCode())
                .isEqualTo(503);
    }

    @Test
    void thePictureIsDrawnOnTheFirstRequestForItAndOnlyOnce() throws Exception {
        monitor.close();
        java.util.concurrent.atomic.AtomicInteger drawn = new java.util.concurrent.atomic.AtomicInteger();
        monitor = Monitor.start("127.0.0.1", 0, graph, () -> {
            drawn.incrementAndGet();
            return "<svg xmlns=\"http://www.w3.org/2000/svg\" id=\"drawn\"/>";
        });
        assertThat(get("/status.json").statusCode()).isEqualTo(200);
        assertThat(drawn).hasValue(0);
        assertThat(get("/graph.svg").body()).contains("id=\"drawn\"");
        assertThat(get("/graph.svg").body()).contains("id=\"drawn\"");
        assertThat(drawn).hasValue(1);
    }

    @Test
    void preloadingStartsNoThreadOfJettys() {
        java.util.Set<Thread> before = Thread.getAllStackTraces().keySet();
        Monitor.preload();
        assertThat(Thread.getAllStackTraces().keySet())
                .filteredOn(t -> t.getName().startsWith("qtp") && !before.contains(t)).isEmpty();
    }

    private HttpResponse<String> get(String path) throws Exception {
        return http.send(HttpRequest.newBuilder(uri(path)).GET().build(), HttpResponse.BodyHandlers.ofString());
    }

    private URI uri(String path) {
        return URI.create("http://127.0.0.1:" + monitor.port() + path);
    }

    /** A page's WebSocket; one that does not read asks for one message and then never for more. */
    private final class Page implements WebSocket.Listener {
        final LinkedBlockingQueue<JsonNode> received = new LinkedBlockingQueue<>();
        final WebSocket socket;
        private final boolean reading;
        private final StringBuilder partial = new StringBuilder();

        Page() throws Exception {
            this(true);
        }

        Page(boolean reading) throws Exception {
            this.reading = reading;
            socket = http.newWebSocketBuilder().buildAsync(URI.create("ws://127.0.0.1:" + monitor.port() + "/live"), this)
                    .get(10, TimeUnit.SECONDS);
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                try {
                    received.add(JSON.readTree(partial.toString()));
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
                partial.setLength(0);
            }
            if (reading) {
                ws.request(1);
            }
            return null;
        }

        JsonNode poll(Predicate<JsonNode> test) throws InterruptedException {
            JsonNode m;
            while ((m = received.poll(20, TimeUnit.MILLISECONDS)) != null) {
                if (test.test(m)) {
                    return m;
                }
            }
            return null;
        }

        JsonNode await(Predicate<JsonNode> test) throws InterruptedException {
            long deadline = System.currentTimeMillis() + 15_000;
            while (System.currentTimeMillis() < deadline) {
                JsonNode m = received.poll(100, TimeUnit.MILLISECONDS);
                if (m != null && test.test(m)) {
                    return m;
                }
            }
            throw new AssertionError("no such message within 15 s");
        }
    }
}
