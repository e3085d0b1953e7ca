package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import org.habla.recording.RecordedEvent;
import org.habla.recording.Recording;

/**
 * An MCAP recording read by two independent readers — the official Python {@code mcap} package
 * ({@code src/test/python/mcap_check.py}) and the official TypeScript {@code @mcap/core} with CRC validation of
 * every chunk, the data section and the summary ({@code src/test/node/mcap-check.mjs}) — which must find every
 * message HABLA's own reader finds, topic by topic, and the channels, schemas and metadata HABLA wrote.
 */
final class McapCheck {

    private static final ObjectMapper JSON = new ObjectMapper();

    private McapCheck() {
    }

    static void independentReadersAgree(Path file, Recording ours) throws Exception {
        Map<String, Integer> expected = new TreeMap<>();
        for (RecordedEvent e : ours.events()) {
            expected.merge(topic(e), 1, Integer::sum);
        }
        JsonNode py = run(Path.of("src/test/python"), "python3", "mcap_check.py", file.toAbsolutePath().toString());
        assertThat(counts(py.path("topics"))).as("messages per topic read by Python's mcap").isEqualTo(expected);
        assertThat(py.at("/statistics/messageCount").asInt()).isEqualTo(ours.events().size());
        assertThat(py.path("schemaEncodings").toString()).isEqualTo("[\"jsonschema\"]");
        assertThat(py.at("/channels/~1distance~1distance_angle/encoding").asText()).isEqualTo("json");
        assertThat(py.at("/channels/~1distance~1distance_angle/schema").asText()).isEqualTo("habla.output.record");
        assertThat(py.at("/metadata/habla.recording").toString()).contains("config", "header", "version");

        JsonNode ts = run(Path.of("src/test/node"), "node", "mcap-check.mjs", file.toAbsolutePath().toString());
        assertThat(ts.has("error")).as("@mcap/core: %s", ts.path("error").asText()).isFalse();
        assertThat(counts(ts.path("topics"))).as("messages per topic read by @mcap/core").isEqualTo(expected);
        assertThat(ts.path("indexedMessages").asInt()).isEqualTo(ours.events().size());
        assertThat(ts.at("/records/Message").asInt()).as("messages the CRC-checking stream reader took out of the chunks")
                .isEqualTo(ours.events().size());
        assertThat(ts.path("chunkIndexes").asInt()).isEqualTo(ts.at("/statistics/chunkCount").asInt()).isPositive();
        assertThat(ts.at("/records/DataEnd").asInt()).isEqualTo(1);
        assertThat(ts.at("/records/Footer").asInt()).isEqualTo(1);
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

    private static Map<String, Integer> counts(JsonNode topics) {
        Map<String, Integer> m = new TreeMap<>();
        topics.properties().forEach(e -> m.put(e.getKey(), e.getValue().asInt()));
        return m;
    }

    private static JsonNode run(Path dir, String... command) throws Exception {
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(false).start();
        byte[] out = p.getInputStream().readAllBytes();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("%s failed: %s %s", String.join(" ", command),
                new String(out, StandardCharsets.UTF_8), err).isZero();
        return JSON.readTree(out);
    }
}
