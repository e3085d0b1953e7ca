package org.habla.drivers.iface;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.LinkSession;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The interface protocol over real loopback sockets: the test plays the interface program (a TCP server), HABLA's
 * side is the driver's session, as the engine would run it.
 */
@Timeout(30)
class InterfaceSessionTest {

    private static final String HELLO = "{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"rover\","
            + "\"channels\":["
            + "{\"name\":\"ir\",\"direction\":\"reading\",\"kind\":\"vector\",\"unit\":\"m\",\"meta\":{\"count\":8}},"
            + "{\"name\":\"bumper\",\"direction\":\"reading\",\"kind\":\"record\"},"
            + "{\"name\":\"eye\",\"direction\":\"reading\",\"kind\":\"image\"},"
            + "{\"name\":\"wheels\",\"direction\":\"command\",\"kind\":\"vector\",\"unit\":\"m/s\",\"motion\":true},"
            + "{\"name\":\"lamp\",\"direction\":\"command\",\"kind\":\"number\"},"
            + "{\"name\":\"horn\",\"direction\":\"command\",\"kind\":\"text\"}]}";

    private static final String PARAMS = "{\"channels\":["
            + "{\"name\":\"ir\",\"direction\":\"reading\",\"kind\":\"vector\",\"unit\":\"m\"},"
            + "{\"name\":\"bumper\",\"direction\":\"reading\",\"kind\":\"record\"},"
            + "{\"name\":\"eye\",\"direction\":\"reading\",\"kind\":\"image\"},"
            + "{\"name\":\"wheels\",\"direction\":\"command\",\"kind\":\"vector\",\"unit\":\"m/s\",\"motion\":true},"
            + "{\"name\":\"lamp\",\"direction\":\"command\",\"kind\":\"number\"}],\"keepAliveMs\":250}";

    private ServerSocket program;
    private Socket habla;
    private Socket robot;
    private InputStream hablaIn;
    private OutputStream hablaOut;
    private FrameReader robotReads;
    private LinkSession session;
    private final RecordingSink sink = new RecordingSink();

    @BeforeEach
    void connect() throws IOException {
        program = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        InterfaceParams params = ParamsJson.of(InterfaceParams.class, PARAMS);
        Driver driver = new InterfaceProtocolDriverProvider().create(
                InterfaceAddress.parse("127.0.0.1:" + program.getLocalPort()), params);
        Connection connection = driver.connections().get(0);
        assertThat(connection.port()).isEqualTo(program.getLocalPort());
        assertThat(connection.commandChannels()).containsExactlyInAnyOrder("wheels", "lamp");
        session = connection.sessions().get();
        habla = new Socket(InetAddress.getLoopbackAddress(), connection.port());
        habla.setSoTimeout(5_000);
        robot = program.accept();
        robot.setSoTimeout(5_000);
        hablaIn = habla.getInputStream();
        hablaOut = habla.getOutputStream();
        robotReads = new FrameReader(robot.getInputStream(), 65_536, 1 << 20);
    }

    @AfterEach
    void close() throws IOException {
        habla.close();
        robot.close();
        program.close();
    }

    private void robotSends(String lines) throws IOException {
        robot.getOutputStream().write(lines.getBytes(UTF_8));
        robot.getOutputStream().flush();
    }

    @Test
    void theHandshakeAcceptsAHelloThatOffersEveryConfiguredChannel() throws Exception {
        robotSends(HELLO + "\n");
        session.handshake(hablaIn, hablaOut, sink);
        assertThat(sink.info).hasSize(1);
        assertThat(sink.info.get(0).path("robot").asText()).isEqualTo("rover");
        assertThat(sink.info.get(0).path("channels").size()).isEqualTo(6);
        assertThat(sink.malformed).isEmpty();
    }

    @Test
    void theHandshakeRejectsAMissingChannelOrAWrongKindOrDirection() throws Exception {
        robotSends("{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"rover\",\"channels\":["
                + "{\"name\":\"ir\",\"direction\":\"reading\",\"kind\":\"number\"},"
                + "{\"name\":\"bumper\",\"direction\":\"command\",\"kind\":\"record\"},"
                + "{\"name\":\"eye\",\"direction\":\"reading\",\"kind\":\"image\"},"
                + "{\"name\":\"wheels\",\"direction\":\"command\",\"kind\":\"vector\",\"motion\":true}]}\n");
        assertThatThrownBy(() -> session.handshake(hablaIn, hablaOut, sink))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("'rover'")
                .hasMessageContaining("channel 'ir' is announced as a number reading, the config expects a vector reading")
                .hasMessageContaining("channel 'bumper' is announced as a record command")
                .hasMessageContaining("channel 'lamp' is not announced");
    }

    @Test
    void theHandshakeRejectsAnotherProtocolOrAFirstLineThatIsNoHello() throws Exception {
        robotSends("{\"type\":\"hello\",\"protocol\":\"habla-interface/9\",\"channels\":[]}\n");
        assertThatThrownBy(() -> session.handshake(hablaIn, hablaOut, sink))
                .hasMessageContaining("speaks protocol \"habla-interface/9\"");
        LinkSession fresh = new InterfaceProtocolDriverProvider().create(InterfaceAddress.parse("localhost"),
                ParamsJson.of(InterfaceParams.class, PARAMS)).connections().get(0).sessions().get();
        robotSends("{\"type\":\"reading\",\"channel\":\"ir\",\"value\":[1]}\n");
        assertThatThrownBy(() -> fresh.handshake(hablaIn, hablaOut, sink)).hasMessageContaining("must be a hello");
    }

    @Test
    void readingsAreDecodedWithTheirTimesAndKinds() throws Exception {
        robotSends(HELLO + "\n"
                + "{\"type\":\"reading\",\"channel\":\"ir\",\"t\":1763798400123456,\"value\":[0.5,null,2]}\n"
                + "{\"type\":\"reading\",\"channel\":\"bumper\",\"value\":{\"hit\":true}}\n"
                + "{\"type\":\"reading\",\"channel\":\"eye\",\"kind\":\"image\",\"width\":2,\"height\":1,"
                + "\"encoding\":\"gray8\",\"bytes\":2}\n\n\u0007{\"type\":\"pong\"}\n");
        session.handshake(hablaIn, hablaOut, sink);
        for (int i = 0; i < 3; i++) {
            session.readNext(hablaIn, sink);
        }
        session.readNext(hablaIn, sink); // the pong after the image's two bytes
        assertThat(sink.readings).containsExactly(
                new RecordingSink.Reading("ir", VectorValue.of(0.5, Double.NaN, 2), 1_763_798_400_123_456L),
                new RecordingSink.Reading("bumper", RecordValue.builder().put("hit", true).build(), -1),
                new RecordingSink.Reading("eye", ImageFrame.of(2, 1, "gray8", new byte[] {'\n', 7}), -1));
        assertThat(sink.malformed).isEmpty();
    }

    @Test
    void malformedLinesAreCountedAndTheConnectionGoesOn() throws Exception {
        robotSends(HELLO + "\n"
                + "{\"type\":\"reading\",\"channel\":\"sonar\",\"value\":[1]}\n"
                + "{\"type\":\"reading\",\"channel\":\"ir\",\"value\":\"near\"}\n"
                + "{\"type\":\"reading\",\"channel\":\"ir\",\"t\":\"soon\",\"value\":[1]}\n"
                + "{\"type\":\"reading\",\"channel\":\"wheels\",\"value\":[1,1]}\n"
                + "not json at all\n"
                + "{\"type\":\"dance\"}\n"
                + "{\"type\":\"reading\",\"channel\":\"ir\",\"value\":[3]}\n");
        session.handshake(hablaIn, hablaOut, sink);
        for (int i = 0; i < 7; i++) {
            session.readNext(hablaIn, sink);
        }
        assertThat(sink.malformed).hasSize(6);
        assertThat(sink.malformed.get(0)).contains("unknown channel 'sonar'");
        assertThat(sink.malformed.get(1)).contains("channel 'ir'", "expected an array of numbers");
        assertThat(sink.malformed.get(2)).contains("\"t\" must be microseconds");
        assertThat(sink.malformed.get(3)).contains("unknown channel 'wheels'");
        assertThat(sink.malformed.get(4)).startsWith("bad_json");
        assertThat(sink.malformed.get(5)).contains("'dance'");
        assertThat(sink.readings).containsExactly(new RecordingSink.Reading("ir", VectorValue.of(3), -1));
    }

    @Test
    void theStreamEndingIsAnErrorThatEndsTheConnection() throws Exception {
        robotSends(HELLO + "\n{\"type\":\"reading\",\"channel\":\"eye\",\"kind\":\"image\",\"width\":2,"
                + "\"height\":1,\"encoding\":\"gray8\",\"bytes\":2}\nx");
        session.handshake(hablaIn, hablaOut, sink);
        robot.shutdownOutput();
        assertThatThrownBy(() -> session.readNext(hablaIn, sink)).isInstanceOf(IOException.class)
                .hasMessageContaining("truncated");
    }

    @Test
    void commandsStopPingsAndByeAreEncodedAsFrames() throws Exception {
        robotSends(HELLO + "\n");
        session.handshake(hablaIn, hablaOut, sink);
        session.write("wheels", VectorValue.of(0.2, -0.2), hablaOut);
        session.write("lamp", new NumberValue(1), hablaOut);
        session.stopMotion(hablaOut);
        session.keepAlive(hablaOut);
        session.goodbye(hablaOut);
        assertThat(line()).isEqualTo("{\"type\":\"command\",\"channel\":\"wheels\",\"kind\":\"vector\",\"value\":[0.2,-0.2]}");
        assertThat(line()).isEqualTo("{\"type\":\"command\",\"channel\":\"lamp\",\"kind\":\"number\",\"value\":1.0}");
        assertThat(line()).isEqualTo("{\"type\":\"stop\"}");
        assertThat(line()).isEqualTo("{\"type\":\"ping\"}");
        assertThat(line()).isEqualTo("{\"type\":\"bye\"}");
        assertThat(session.keepAlivePeriod()).contains(Duration.ofMillis(250));
        assertThatThrownBy(() -> session.write("horn", new NumberValue(1), hablaOut))
                .hasMessageContaining("no command channel 'horn'");
    }

    @Test
    void theDriverIsFoundByItsNameThroughServiceDiscovery() {
        PluginRegistry registry = PluginRegistry.discover();
        assertThat(registry.driver("habla")).get().isInstanceOf(InterfaceProtocolDriverProvider.class);
        assertThat(registry.driver("habla").get().paramsType()).isEqualTo(InterfaceParams.class);
    }

    private String line() throws IOException {
        Frame f = robotReads.read();
        return f.header().toString();
    }

    @Test
    void paramsRequireChannelsAndCheckThem() {
        ObjectMapper json = new ObjectMapper();
        assertThatThrownBy(() -> ParamsJson.of(InterfaceParams.class, "{}")).hasMessageContaining("channels:");
        assertThatThrownBy(() -> ParamsJson.of(InterfaceParams.class, "{\"channels\":[{\"name\":\"ir\",\"direction\":\"up\",\"kind\":\"vector\"}]}")).hasMessageContaining("direction: channel 'ir' has direction 'up'");
        assertThatThrownBy(() -> ParamsJson.of(InterfaceParams.class, "{\"channels\":[{\"name\":\"link\",\"direction\":\"reading\","
                + "\"kind\":\"record\"}]}")).hasMessageContaining("'link' is the engine's");
        assertThatThrownBy(() -> ParamsJson.of(InterfaceParams.class, "{\"channels\":[{\"name\":\"a\",\"direction\":\"reading\","
                + "\"kind\":\"number\",\"motion\":true}]}")).hasMessageContaining("motion");
        assertThatThrownBy(() -> ParamsJson.of(InterfaceParams.class, PARAMS.replace("250", "5")))
                .hasMessageContaining("$.params.keepAliveMs: must be within [50, 60000], was 5");
        List<String> names = ParamsJson.of(InterfaceParams.class,
                "{\"channels\":[{\"name\":\"ir\",\"direction\":\"reading\",\"kind\":\"vector\"}]}")
                .descriptors().stream().map(d -> d.name() + ":" + d.unit()).toList();
        assertThat(names).containsExactly("ir:");
    }
}
