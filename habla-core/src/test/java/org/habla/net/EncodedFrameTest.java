package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import org.junit.jupiter.api.Test;

class EncodedFrameTest {

    @Test
    void theLineIsTheHeaderAsCompactJsonEndedByOneNewline() {
        ObjectNode header = JsonNodeFactory.instance.objectNode().put("type", "sample").put("seq", 7);
        EncodedFrame encoded = EncodedFrame.of(Frame.of(header));
        assertThat(new String(encoded.line(), UTF_8)).isEqualTo("{\"type\":\"sample\",\"seq\":7}\n");
        assertThat(encoded.type()).isEqualTo("sample");
    }

    @Test
    void aBodyIsDeclaredWithItsLengthWithoutChangingTheFramesHeader() {
        ObjectNode header = JsonNodeFactory.instance.objectNode().put("type", "sample");
        EncodedFrame encoded = EncodedFrame.of(new Frame(header, new byte[] {1, 2, 3}));
        assertThat(new String(encoded.line(), UTF_8)).isEqualTo("{\"type\":\"sample\",\"bytes\":3}\n");
        assertThat(header.has("bytes")).isFalse();
    }

    @Test
    void oneEncodingWrittenByTwoWritersReadsBackAsTheSameFrameFromBoth() throws Exception {
        ObjectNode header = JsonNodeFactory.instance.objectNode().put("type", "sample").put("output", "image");
        EncodedFrame once = EncodedFrame.of(new Frame(header, "pixels".getBytes(UTF_8)));
        for (int writer = 0; writer < 2; writer++) {
            ByteArrayOutputStream wire = new ByteArrayOutputStream();
            FrameWriter out = new FrameWriter(wire);
            out.write(once);
            out.flush();
            Frame back = new FrameReader(new ByteArrayInputStream(wire.toByteArray()), 1_024, 1_024).read();
            assertThat(back.header().path("output").asText()).isEqualTo("image");
            assertThat(new String(back.body(), UTF_8)).isEqualTo("pixels");
        }
    }
}
