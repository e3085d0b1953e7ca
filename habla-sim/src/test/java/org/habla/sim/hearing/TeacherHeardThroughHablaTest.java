package org.habla.sim.hearing;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.habla.sim.aibo.AiboSimulator;
import org.habla.sim.aibo.TekkotsuPorts;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The teacher's commands heard through HABLA as a user runs it: the simulated robot's microphone served
 * on loopback, the daemon in a process of its own with the audio methods, and a control client on the
 * exposed socket. The Pioneer's teacher plays notes into the laptop microphone (pcm-stream); the
 * Aibo's teacher speaks into its ears (Tekkotsu's microphone server), recognised by Sphinx-4.
 */
@Timeout(300)
class TeacherHeardThroughHablaTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long HEAR_MS = 30_000;
    /** The wait for a recogniser to load its model: beside a busy build, Sphinx-4 took more than 30 s. */
    private static final long READY_MS = 120_000;

    private static ObjectNode method(ArrayNode methods, String id, String type, String layer, String input,
            String source) {
        ObjectNode m = methods.addObject().put("id", id).put("type", type).put("layer", layer);
        m.putObject("inputs").put(input, source);
        return m;
    }

    /** A control client on an exposed text socket: the values of the samples it reads. */
    private static final class TextSocket implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;

        TextSocket(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(500);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            JsonNode hello = JSON.readTree(readLine(10_000));
            assertThat(hello.path("type").asText()).isEqualTo("hello");
        }

        private String readLine(long millis) throws IOException {
            long end = System.currentTimeMillis() + millis;
            while (System.currentTimeMillis() < end) {
                try {
                    String line = in.readLine();
                    if (line == null) {
                        throw new IOException("the daemon closed the socket");
                    }
                    return line;
                } catch (SocketTimeoutException e) {
                    // keep waiting until the deadline
                }
            }
            return null;
        }

        /** The next text sample's value, or null after {@code millis}. */
        String nextText(long millis) throws IOException {
            long end = System.currentTimeMillis() + millis;
            while (System.currentTimeMillis() < end) {
                String line = readLine(end - System.currentTimeMillis());
                if (line == null) {
                    return null;
                }
                JsonNode n = JSON.readTree(line);
                if (n.path("type").asText().equals("sample")) {
                    return n.path("value").asText();
                }
            }
            return null;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    /** The daemon's status snapshot, or null if the endpoint does not answer. */
    private static JsonNode status(int port) {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(2000);
            String line = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8)).readLine();
            return line == null ? null : JSON.readTree(line);
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Waits until {@code listener} is ready and the audio reaching {@code analyser} has kept flowing for
     * a second (the links settle after the robot's servers start): a command given before would fall
     * into a gap of the stream and never be heard.
     */
    private static void awaitListening(int statusPort, String analyser, String listener) throws InterruptedException {
        long end = System.currentTimeMillis() + READY_MS;
        long flowingSince = -1;
        long lastHandled = -1;
        while (System.currentTimeMillis() < end) {
            JsonNode st = status(statusPort);
            boolean ready = false;
            long handled = -1;
            if (st != null) {
                for (JsonNode m : st.path("methods")) {
                    if (m.path("id").asText().equals(listener)) {
                        ready = m.path("ready").asBoolean(false);
                    }
                    if (m.path("id").asText().equals(analyser)) {
                        handled = m.path("handled").asLong(-1);
                    }
                }
            }
            long now = System.currentTimeMillis();
            boolean flowing = handled > lastHandled && lastHandled >= 0;
            flowingSince = flowing ? (flowingSince < 0 ? now : flowingSince) : -1;
            lastHandled = handled;
            if (ready && flowingSince >= 0 && now - flowingSince >= 1000) {
                return;
            }
            Thread.sleep(200);
        }
        throw new AssertionError("the daemon did not start listening within " + READY_MS + " ms: " + status(statusPort));
    }

    /** Waits until the daemon's status says the interface connection {@code name} is up. */
    private static void awaitConnectionUp(int statusPort, String name) throws InterruptedException {
        long end = System.currentTimeMillis() + HEAR_MS;
        while (System.currentTimeMillis() < end) {
            JsonNode st = status(statusPort);
            if (st != null) {
                for (JsonNode c : st.path("interfaces").path(0).path("connections")) {
                    if (c.path("name").asText().equals(name) && c.path("up").asBoolean()) {
                        return;
                    }
                }
            }
            Thread.sleep(50);
        }
        throw new AssertionError("connection " + name + " not up within " + HEAR_MS + " ms: " + status(statusPort));
    }

    @Test
    void thePioneerTeachersNotesArriveAsNoteNames(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(2);
        try (PioneerSim sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 2));
                TruthClient truth = new TruthClient(sim.truthPort())) {
            ObjectNode c = JSON.createObjectNode().put("system", "pioneer-ears");
            c.putObject("status").put("port", ports[1]);
            c.putArray("interfaces").addObject().put("id", "mic").put("driver", "pcm-stream")
                    .put("address", "127.0.0.1:" + sim.micPort())
                    .putObject("params").put("rateHz", 16_000).put("channels", 1).put("bits", 16).put("chunkMs", 50);
            ArrayNode m = c.putArray("methods");
            method(m, "microphone", "microphone", "sensors_actuators", "audio", "@mic.audio");
            method(m, "notes", "note-recognition", "processing", "audio", "microphone.audio")
                    .putObject("params").putArray("notes").add("C5").add("E5").add("G5").add("C6");
            ObjectNode out = method(m, "note", "pass-through", "virtual", "in", "notes.note");
            out.putObject("params").put("kind", "text");
            out.putObject("expose").put("port", ports[0]).put("name", "note");
            Path cfg = tmp.resolve("pioneer-ears.json");
            Files.writeString(cfg, c.toPrettyString());

            try (DaemonProcess daemon = DaemonProcess.start(tmp.resolve("daemon.log"), "run", cfg.toString())) {
                assertThat(DaemonProcess.awaitPort(ports[0], DaemonProcess.START_MS)).as(daemon.output()).isTrue();
                try (TextSocket notes = new TextSocket(ports[0])) {
                    awaitListening(ports[1], "notes", "notes");
                    Map<String, String> expected = Map.of("forward", "C5", "left", "E5", "right", "G5", "back", "C6");
                    List<String> heard = new ArrayList<>();
                    for (String label : List.of("forward", "left", "right", "back", "left")) {
                        assertThat(truth.op("{\"op\":\"note\",\"label\":\"" + label + "\"}").has("ok")).isTrue();
                        String note = notes.nextText(HEAR_MS);
                        heard.add(note);
                        assertThat(note).as("note for %s; daemon log:%n%s", label, daemon.output())
                                .isEqualTo(expected.get(label));
                    }
                    System.out.printf("end to end: the Pioneer's teacher played %s%n", heard);
                }
            }
        }
    }

    @Test
    void theAiboTeachersWordsArriveAsPhrases(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(2);
        try (AiboSimulator sim = new AiboSimulator(new AiboSimulator.Options(World.builtIn("aibo-arena"), 2, 5,
                TekkotsuPorts.ANY_FREE, 0, false))) {
            sim.start();
            try (TruthClient truth = new TruthClient(sim.truthPort())) {
                TekkotsuPorts p = sim.ports();
                ObjectNode c = JSON.createObjectNode().put("system", "aibo-ears");
                c.putObject("status").put("port", ports[1]);
                ObjectNode params = c.putArray("interfaces").addObject().put("id", "aibo").put("driver", "tekkotsu")
                        .put("address", "127.0.0.1").putObject("params");
                params.put("worldStatePort", p.worldState()).put("microphonePort", p.microphone())
                        .put("cameraPort", p.rawCam()).put("walkPort", p.walk()).put("headPort", p.head())
                        .put("speakerPort", p.speaker()).put("eStopPort", p.eStop())
                        .put("controllerPort", p.controller()).put("camera", false);
                ArrayNode m = c.putArray("methods");
                method(m, "ears", "microphone", "sensors_actuators", "audio", "@aibo.audio")
                        .putObject("params").put("downmix", true);
                method(m, "sound", "audio-processing", "processing", "audio", "ears.audio");
                method(m, "speech", "speech-recognition", "processing", "segments", "sound.segments");
                ObjectNode out = method(m, "words", "pass-through", "virtual", "in", "speech.words");
                out.putObject("params").put("kind", "text");
                out.putObject("expose").put("port", ports[0]).put("name", "words");
                Path cfg = tmp.resolve("aibo-ears.json");
                Files.writeString(cfg, c.toPrettyString());

                try (DaemonProcess daemon = DaemonProcess.start(tmp.resolve("daemon.log"), "run", cfg.toString())) {
                    assertThat(DaemonProcess.awaitPort(ports[0], DaemonProcess.START_MS)).as(daemon.output()).isTrue();
                    try (TextSocket words = new TextSocket(ports[0])) {
                        awaitListening(ports[1], "sound", "speech");
                        Map<String, String> expected = Map.of("forward", "go forward", "left", "turn left",
                                "right", "turn right", "back", "go back");
                        List<String> heard = new ArrayList<>();
                        // a phrase said before the daemon's microphone link is up is partly lost, as in a room
                        awaitConnectionUp(ports[1], "microphone");
                        for (String label : List.of("forward", "left", "right", "back")) {
                            assertThat(truth.op("{\"op\":\"say\",\"label\":\"" + label + "\"}").has("ok")).isTrue();
                            String phrase = words.nextText(HEAR_MS);
                            heard.add(phrase);
                            assertThat(phrase).as("words for %s; daemon log:%n%s", label, daemon.output())
                                    .isEqualTo(expected.get(label));
                        }
                        System.out.printf("end to end: the Aibo's teacher said %s%n", heard);
                    }
                }
            }
        }
    }
}
