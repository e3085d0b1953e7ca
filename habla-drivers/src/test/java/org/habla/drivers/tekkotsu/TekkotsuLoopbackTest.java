package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The whole driver against tiny stand-ins for every Tekkotsu server, over real loopback sockets. */
class TekkotsuLoopbackTest {

    private static final Duration LIMIT = Duration.ofSeconds(15);
    private static final String STOP = "66 00 00 00 00 73 00 00 00 00 72 00 00 00 00";

    private final Map<String, TinyServer> servers = new LinkedHashMap<>();
    private final List<LoopbackLink> links = new ArrayList<>();
    private final RecordingSink sink = new RecordingSink();

    @AfterEach
    void closeEverything() throws IOException {
        for (LoopbackLink l : links) {
            l.close();
        }
        for (TinyServer s : servers.values()) {
            s.close();
        }
    }

    @Test
    void everyServerSpeaksItsProtocolWithTheDriver() throws Exception {
        byte[] jpeg = RawCamSessionTest.jpeg(104, 80, BufferedImage.TYPE_INT_RGB);
        servers.put("worldstate", new TinyServer((out, s) -> {
            byte[] three = WorldStateSessionTest.concat(TekkotsuPackets.ers7WorldState(),
                    TekkotsuPackets.ers7WorldState(), TekkotsuPackets.ers7WorldState());
            writeInPieces(out, three, 100);
            s.holdOpen();
        }));
        servers.put("microphone", new TinyServer((out, s) -> {
            byte[] packet = TekkotsuPackets.microphone(0, 16_000, 16, 1, MicrophoneSessionTest.stereoRamp());
            writeInPieces(out, WorldStateSessionTest.concat(packet, packet), 700);
            s.holdOpen();
        }));
        servers.put("camera", new TinyServer((out, s) -> {
            writeInPieces(out, RawCamSessionTest.jpegColourPacket(jpeg, 1), 1000);
            s.holdOpen();
        }));
        servers.put("walk", new TinyServer((out, s) -> s.holdOpen()));
        servers.put("head", new TinyServer((out, s) -> s.holdOpen()));
        servers.put("speaker", new TinyServer((out, s) -> s.holdOpen()));
        servers.put("estop", new TinyServer((out, s) -> {
            TinyServer.await(LIMIT, () -> s.receivedText().contains("start\n"));
            out.write("off\n".getBytes());
            out.flush();
            s.holdOpen();
        }));
        servers.put("controller", new TinyServer((out, s) -> {
            TinyServer.await(LIMIT, () -> s.receivedText().contains("!select \"-RawCam\"\n"));
            out.write("hello\n1\nrefresh\nroot\n0\n".getBytes());
            out.flush();
            s.holdOpen();
        }));
        String params = """
                {"worldStatePort": %d, "microphonePort": %d, "cameraPort": %d, "walkPort": %d, "headPort": %d,
                 "speakerPort": %d, "eStopPort": %d, "controllerPort": %d, "walkResendMs": 100}"""
                .formatted(port("worldstate"), port("microphone"), port("camera"), port("walk"), port("head"),
                        port("speaker"), port("estop"), port("controller"));
        Driver driver = new TekkotsuDriverProvider().create(InterfaceAddress.parse("127.0.0.1"),
                ParamsJson.of(TekkotsuParams.class, params));
        Map<String, LoopbackLink> byName = new LinkedHashMap<>();
        for (Connection c : driver.connections()) {
            LoopbackLink link = new LoopbackLink(c.port(), c, sink);
            links.add(link);
            byName.put(c.name(), link);
        }

        assertThat(TinyServer.await(LIMIT, () -> sink.on("ir").size() == 3)).isTrue();
        assertThat(TinyServer.await(LIMIT, () -> sink.on("audio").size() == 2)).isTrue();
        assertThat(TinyServer.await(LIMIT, () -> sink.on("camera").size() == 1)).isTrue();
        assertThat(((ImageFrame) sink.on("camera").get(0)).data()).isEqualTo(jpeg);
        assertThat(((AudioChunk) sink.on("audio").get(1)).pcm()).isEqualTo(MicrophoneSessionTest.stereoRamp());

        byName.get("walk").write("walk", VectorValue.of(0.09, 0, 0));
        String forward = "66 00 00 00 3f 73 00 00 00 00 72 00 00 00 00";
        assertThat(TinyServer.await(LIMIT, () -> hex(servers.get("walk").received()).startsWith(STOP + " " + forward
                + " " + forward))).as("handshake stop, the command, then its re-sending").isTrue();
        byName.get("walk").stopMotion();
        assertThat(TinyServer.await(LIMIT, () -> hex(servers.get("walk").received()).contains(forward + " " + STOP)))
                .isTrue();

        byName.get("head").write("head", VectorValue.of(0, Math.toRadians(44), 0));
        assertThat(TinyServer.await(LIMIT, () -> servers.get("head").received().length == 15)).isTrue();
        assertThat(HeadSessionTest.values(servers.get("head").received())).containsExactly(0f, 0.5f, 0f);

        byName.get("speaker").write("speaker", AudioChunk.of(AudioFormat.MONO_16K, new byte[320]));
        assertThat(TinyServer.await(LIMIT, () -> servers.get("speaker").received().length == 328)).isTrue();
        assertThat(ByteBuffer.wrap(servers.get("speaker").received()).order(ByteOrder.LITTLE_ENDIAN).getShort(0))
                .isEqualTo((short) 324);

        assertThat(TinyServer.await(LIMIT, () -> sink.info.stream().anyMatch(n -> n.has("eStop")))).isTrue();
        assertThat(TinyServer.await(LIMIT, () -> sink.info.stream().anyMatch(n -> n.has("controllerHellos"))))
                .isTrue();
        assertThat(servers.get("controller").receivedText()).startsWith("!hello\n!set vision.rawcam.transport=TCP\n")
                .contains("!select \"World State Serializer\"\n!select \"-World State Serializer\"\n");

        byName.get("estop").close();
        assertThat(TinyServer.await(LIMIT, () -> servers.get("estop").receivedText().equals("refresh\nstart\nstop\n")))
                .isTrue();
        assertThat(sink.malformed).isEmpty();
        for (String quiet : List.of("walk", "head", "speaker", "controller")) {
            assertThat(byName.get(quiet).ended.get()).as(quiet + " link survives a quiet server").isNull();
        }
    }

    @Test
    void aServerThatVanishesMidPacketEndsOnlyItsOwnLink() throws Exception {
        servers.put("worldstate", new TinyServer((out, s) -> {
            out.write(TekkotsuPackets.ers7WorldState());
            out.write(Arrays.copyOf(TekkotsuPackets.ers7WorldState(), 100));
            out.flush();
            s.hangUp();
        }));
        servers.put("walk", new TinyServer((out, s) -> s.holdOpen()));
        Driver driver = new TekkotsuDriverProvider().create(InterfaceAddress.parse("127.0.0.1"),
                ParamsJson.of(TekkotsuParams.class, """
                        {"worldStatePort": %d, "walkPort": %d, "head": false, "eStop": false, "microphone": false,
                         "speaker": false, "camera": false, "controller": false}"""
                        .formatted(port("worldstate"), port("walk"))));
        LoopbackLink world = new LoopbackLink(port("worldstate"), driver.connections().get(0), sink);
        LoopbackLink walk = new LoopbackLink(port("walk"), driver.connections().get(1), sink);
        links.add(world);
        links.add(walk);

        assertThat(TinyServer.await(LIMIT, () -> world.ended.get() != null)).isTrue();
        assertThat(world.ended.get()).hasMessageContaining("stream ended");
        assertThat(sink.on("joints")).hasSize(1);
        walk.write("walk", VectorValue.of(0, 0, 0.9));
        assertThat(TinyServer.await(LIMIT, () -> servers.get("walk").received().length >= 30)).isTrue();
        assertThat(walk.ended.get()).isNull();
    }

    private int port(String name) {
        return servers.get(name).port();
    }

    private static String hex(byte[] b) {
        return HexFormat.ofDelimiter(" ").formatHex(b);
    }

    private static void writeInPieces(OutputStream out, byte[] data, int piece) throws IOException,
            InterruptedException {
        for (int at = 0; at < data.length; at += piece) {
            out.write(data, at, Math.min(piece, data.length - at));
            out.flush();
            Thread.sleep(2); // the pieces arrive apart, as from a robot: the decoder must join them
        }
    }
}
