package org.habla.recording;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Base64;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.net.Frame;

/**
 * A recording in MCAP: one channel per interface channel, exposed method output, control socket input and
 * engine event, JSON messages with a JSON Schema per message shape, and the recording's header as metadata.
 *
 * <pre>
 *   topic                      message (the record of the line format, see {@link RecordingCodec})
 *   /@IFACE/CHANNEL            reading or command   {"type":"reading","t","iface","channel","producer","seq",
 *   /METHOD/OUTPUT             output                 "src","stale","kind","value" | format fields, "bytes",
 *   /control/SOCKET/INPUT      control write          "data": base64 of the audio or image bytes}
 *   /habla/link, /habla/tick, /habla/left, /habla/dropped, /habla/end       the engine's events
 *   metadata "habla.recording": {"header": the line format's header record, "config": the config,
 *                                "version": the HABLA version that wrote it}
 * </pre>
 *
 * JPEG and PNG images are also {@code foxglove.CompressedImage} ({@code timestamp}, {@code frame_id},
 * {@code format}, {@code data}), so Foxglove shows them. A message's log time is when HABLA saw the event
 * (the engine clock, ns); its publish time is the source time of the sample's raw reading.
 */
final class McapEventFile implements EventFile {

    static final String METADATA_NAME = "habla.recording";
    static final String PROFILE = "";
    static final String LIBRARY = "HABLA " + McapEventFile.version();

    private static final ObjectMapper JSON = new ObjectMapper();

    private final McapWriter mcap;
    private final Map<String, Integer> channels = new HashMap<>();
    private final Map<String, Integer> schemas = new HashMap<>();
    private final Map<Integer, Long> sequence = new HashMap<>();

    McapEventFile(OutputStream stream, RecordingHeader header) throws IOException {
        mcap = new McapWriter(new java.io.BufferedOutputStream(stream, 1 << 16), PROFILE, LIBRARY);
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("header", JSON.writeValueAsString(RecordingCodec.header(header).header()));
        meta.put("config", JSON.writeValueAsString(header.config()));
        meta.put("version", version());
        mcap.metadata(METADATA_NAME, meta);
        mcap.flushChunk();
    }

    /** The HABLA version in the jar's manifest, or "development" when run from classes. */
    static String version() {
        String v = McapEventFile.class.getPackage().getImplementationVersion();
        return v == null ? "development" : v;
    }

    @Override
    public void write(RecordedEvent e) throws IOException {
        Frame f = RecordingCodec.frame(e);
        ObjectNode m = f.header();
        if (f.hasBody()) {
            m.put("data", Base64.getEncoder().encodeToString(f.body()));
        }
        String topic = topic(e);
        boolean image = m.path("kind").asText().equals("image")
                && (m.path("encoding").asText().equals("jpeg") || m.path("encoding").asText().equals("png"));
        if (image) {
            long src = m.path("src").asLong();
            m.putObject("timestamp").put("sec", src / 1_000_000).put("nsec", (src % 1_000_000) * 1_000);
            m.put("frame_id", m.path("producer").asText());
            m.put("format", m.path("encoding").asText());
        }
        int channel = channel(topic, m.path("type").asText(), m.path("kind").asText(""), image);
        long seq = m.has("seq") ? m.get("seq").asLong() : sequence.merge(channel, 1L, Long::sum);
        long logNs = e.t() * 1_000;
        long publishNs = m.has("src") ? m.get("src").asLong() * 1_000 : logNs;
        mcap.message(channel, seq, logNs, publishNs, JSON.writeValueAsBytes(m));
    }

    @Override
    public void flush() throws IOException {
        mcap.flushChunk();
    }

    @Override
    public void finish() throws IOException {
        mcap.finish();
    }

    static String topic(RecordedEvent e) {
        return switch (e) {
            case RecordedEvent.Reading r -> "/@" + r.iface() + "/" + r.channel();
            case RecordedEvent.Command c -> "/@" + c.iface() + "/" + c.channel();
            case RecordedEvent.ControlWrite w -> "/control/" + w.socket() + "/" + w.input();
            case RecordedEvent.Output o -> "/" + o.method() + "/" + o.output();
            case RecordedEvent.LinkChange l -> "/habla/link";
            case RecordedEvent.WriterLeft w -> "/habla/left";
            case RecordedEvent.Tick k -> "/habla/tick";
            case RecordedEvent.Skip k -> "/habla/skip";
            case RecordedEvent.Dropped d -> "/habla/dropped";
            case RecordedEvent.Audit a -> "/habla/audit";
            case RecordedEvent.End x -> "/habla/end";
        };
    }

    private int channel(String topic, String type, String kind, boolean image) {
        Integer id = channels.get(topic);
        if (id != null) {
            return id;
        }
        String schemaName = image ? "foxglove.CompressedImage" : "habla." + type + (kind.isEmpty() ? "" : "." + kind);
        int schema = schemas.computeIfAbsent(schemaName, n -> {
            int sid = schemas.size() + 1;
            mcap.schema(sid, n, "jsonschema", McapSchemas.of(type, kind, image));
            return sid;
        });
        int cid = channels.size() + 1;
        channels.put(topic, cid);
        mcap.channel(cid, schema, topic, "json", Map.of());
        return cid;
    }
}
