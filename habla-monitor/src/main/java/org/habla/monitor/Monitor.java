package org.habla.monitor;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Supplier;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.HttpStatus;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import org.habla.daemon.LiveGraph;
import org.habla.graph.OutputInfo;
import org.habla.sample.PayloadKind;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The live monitor of a running daemon, on one port (Jetty, loopback unless configured otherwise):
 *
 * <pre>
 *   GET /             the page: the three-layer graph coloured by method state, links, watchdog, sockets;
 *                     a click on a method shows its values, plots, camera frame, phrases, audio level
 *   GET /graph.svg    the graph as {@code habla graph --format svg} draws it
 *   GET /status.json  the newest status the monitor read
 *   WS  /live         the page's updates (status 4 a second, the selected method's values 10 a second)
 *   WS  /             the Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1): every method output
 * </pre>
 *
 * Read-only: no request reaches an input of the graph. Served off the engine's threads: HTTP and WebSocket
 * I/O run on Jetty's threads, updates are assembled on the monitor's own thread, and each page has at most one
 * update in flight.
 */
public final class Monitor implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Monitor.class);
    /** The most pages open on the monitor at once; another is refused with 503. */
    public static final int MAX_PAGES = 16;
    /** The largest message a page may send (a selection is a few dozen bytes). */
    static final int MAX_PAGE_MESSAGE_BYTES = 4_096;
    /** Jetty's threads for the monitor (acceptor, selector and request handling). */
    static final int HTTP_THREADS = 12;

    private final Server server;
    private final MonitorHub hub;
    private final ServerConnector connector;

    private Monitor(Server server, ServerConnector connector, MonitorHub hub) {
        this.server = server;
        this.connector = connector;
        this.hub = hub;
    }

    /**
     * Makes a web server like the monitor's and drops it, unstarted: nothing listens and no thread starts. A daemon
     * runs this on a thread of its own while it checks its ports and builds its graph, so that the classes of Jetty
     * and its WebSocket side are loaded on the other core instead of in {@link #start}, the last step before the
     * ports are served (docs/performance.md (l)).
     */
    public static void preload() {
        Server server = new Server(new QueuedThreadPool(HTTP_THREADS, 2));
        server.addConnector(new ServerConnector(server, 1, 1));
        server.setHandler(WebSocketUpgradeHandler.from(server, container -> { }));
    }

    /**
     * Starts the monitor on {@code bind:port} (port 0: any free port).
     *
     * @param graphSvg the picture of the config, as {@code habla graph --format svg} draws it
     */
    public static Monitor start(String bind, int port, LiveGraph graph, String graphSvg) throws IOException {
        return start(bind, port, graph, () -> graphSvg);
    }

    /**
     * Starts the monitor on {@code bind:port} (port 0: any free port), drawing the picture of the config when it is
     * first asked for: a daemon's ports need not wait for the drawing.
     *
     * @param graphSvg draws the picture of the config, as {@code habla graph --format svg} does; called once
     */
    public static Monitor start(String bind, int port, LiveGraph graph, Supplier<String> graphSvg) throws IOException {
        Objects.requireNonNull(graph, "graph");
        List<OutputInfo> outputs = graph.outputs();
        Map<String, List<String>> inputs = graph.inputs();
        MonitorHub hub = new MonitorHub(graph, id -> view(id, inputs.getOrDefault(id, List.of()), outputs));
        FoxgloveServer foxglove = new FoxgloveServer(outputs, hub.history(), FoxglovePublishing.OFF,
                "HABLA " + graph.status().path("system").asText(), hub);
        QueuedThreadPool threads = new QueuedThreadPool(HTTP_THREADS, 2);
        threads.setName("habla-monitor-http");
        threads.setDaemon(true);
        Server server = new Server(threads);
        ServerConnector connector = new ServerConnector(server, 1, 1);
        connector.setHost(bind);
        connector.setPort(port);
        try {
            // Exactly the address asked for (0.0.0.0 is IPv4 only; see BindAddress); 0: the system's backlog.
            connector.open(org.habla.net.BindAddress.of(bind).listen(port, 0));
        } catch (IOException e) {
            hub.close();
            throw new IOException("the monitor cannot listen on " + bind + ":" + port + ": " + e.getMessage(), e);
        }
        server.addConnector(connector);
        WebSocketUpgradeHandler ws = WebSocketUpgradeHandler.from(server, container -> {
            container.setMaxTextMessageSize(MAX_PAGE_MESSAGE_BYTES);
            container.setIdleTimeout(Duration.ofMinutes(10));
            container.addMapping("/live", (req, resp, cb) -> {
                if (hub.viewerCount() >= MAX_PAGES) {
                    Response.writeError(req, resp, cb, HttpStatus.SERVICE_UNAVAILABLE_503,
                            "the monitor serves at most " + MAX_PAGES + " pages at once (Monitor.MAX_PAGES)");
                    return null;
                }
                return new LiveSocket(hub);
            });
            container.addMapping("/", (req, resp, cb) -> {
                if (!req.hasSubProtocol(FoxgloveSocket.SUBPROTOCOL)) {
                    Response.writeError(req, resp, cb, HttpStatus.BAD_REQUEST_400,
                            "a WebSocket on / speaks the subprotocol " + FoxgloveSocket.SUBPROTOCOL);
                    return null;
                }
                if (foxglove.clientCount() >= FoxgloveServer.MAX_CLIENTS) {
                    Response.writeError(req, resp, cb, HttpStatus.SERVICE_UNAVAILABLE_503, "the monitor serves at most "
                            + FoxgloveServer.MAX_CLIENTS + " Foxglove clients at once (FoxgloveServer.MAX_CLIENTS)");
                    return null;
                }
                resp.setAcceptedSubProtocol(FoxgloveSocket.SUBPROTOCOL);
                return new FoxgloveSocket(foxglove);
            });
        });
        ws.setHandler(new Pages(new WebFiles(), graphSvg, hub));
        server.setHandler(ws);
        try {
            server.start();
        } catch (Exception e) {
            hub.close();
            try {
                server.stop();
            } catch (Exception ignored) {
                // already failing
            }
            throw new IOException("the monitor cannot listen on " + bind + ":" + port + ": " + e.getMessage(), e);
        }
        Monitor m = new Monitor(server, connector, hub);
        LOG.info("monitor on http://{}:{}/", bind, m.port());
        return m;
    }

    /** The bound port. */
    public int port() {
        return connector.getLocalPort();
    }

    @Override
    public void close() {
        hub.close();
        try {
            server.stop();
        } catch (Exception e) {
            LOG.debug("monitor stop: {}", e.toString());
        }
    }

    /** What a page is shown of a method: its outputs and, for drawing its blobs, the camera frames it reads. */
    private static ViewedMethod view(String methodId, List<String> reads, List<OutputInfo> outputs) {
        List<OutputInfo> own = new ArrayList<>();
        String imageSource = null;
        for (OutputInfo o : outputs) {
            if (o.methodId().equals(methodId)) {
                own.add(o);
            }
            if (reads.contains(o.producer()) && o.shape().kind() == PayloadKind.IMAGE) {
                imageSource = o.producer();
            }
        }
        return own.isEmpty() ? null : new ViewedMethod(methodId, own, imageSource);
    }

    /** The plain HTTP side: the page's files, the picture and the newest status; GET only. */
    private static final class Pages extends Handler.Abstract {
        private final WebFiles files;
        private final Supplier<String> drawing;
        private final MonitorHub hub;
        private byte[] svg;

        Pages(WebFiles files, Supplier<String> drawing, MonitorHub hub) {
            this.files = files;
            this.drawing = drawing;
            this.hub = hub;
        }

        /** The picture, drawn on the first request for it. */
        private synchronized byte[] svg() {
            if (svg == null) {
                svg = drawing.get().getBytes(StandardCharsets.UTF_8);
            }
            return svg;
        }

        @Override
        public boolean handle(Request request, Response response, Callback callback) {
            String method = request.getMethod();
            if (!method.equals("GET") && !method.equals("HEAD")) {
                Response.writeError(request, response, callback, HttpStatus.METHOD_NOT_ALLOWED_405,
                        "the monitor is read-only");
                return true;
            }
            String path = Request.getPathInContext(request);
            switch (path) {
                case "/graph.svg" -> send(response, callback, "image/svg+xml; charset=utf-8", svg());
                case "/status.json" -> send(response, callback, "application/json",
                        hub.statusText().getBytes(StandardCharsets.UTF_8));
                default -> {
                    WebFiles.WebFile f = files.get(path);
                    if (f == null) {
                        Response.writeError(request, response, callback, HttpStatus.NOT_FOUND_404, "no such page");
                    } else {
                        send(response, callback, f.contentType(), f.bytes());
                    }
                }
            }
            return true;
        }

        private static void send(Response response, Callback callback, String type, byte[] body) {
            response.setStatus(HttpStatus.OK_200);
            response.getHeaders().put(HttpHeader.CONTENT_TYPE, type);
            response.getHeaders().put(HttpHeader.CACHE_CONTROL, "no-store");
            response.write(true, ByteBuffer.wrap(body), callback);
        }
    }
}
