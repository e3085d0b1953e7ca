package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import org.junit.jupiter.api.Test;

class FrameWriterTest {

    @Test
    void framesWrittenAreReadBackIdentically() throws Exception {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(wire);
        ObjectNode text = JsonNodeFactory.instance.objectNode().put("type", "t").put("s", "line\nbreak \u00e9");
        w.write(text);
        w.write(new Frame(JsonNodeFactory.instance.objectNode().put("type", "b"), new byte[] {'\n', 1, 2}));
        w.flush();

        String first = wire.toString(UTF_8).substring(0, wire.toString(UTF_8).indexOf('\n'));
        assertThat(first).isEqualTo("{\"type\":\"t\",\"s\":\"line\\nbreak \u00e9\"}");
        FrameReader r = new FrameReader(new ByteArrayInputStream(wire.toByteArray()), 1_024, 1_024);
        assertThat(r.read().header()).isEqualTo(text);
        Frame binary = r.read();
        assertThat(binary.header().path("bytes").asInt()).isEqualTo(3);
        assertThat(binary.body()).containsExactly('\n', 1, 2);
        assertThat(r.read()).isNull();
    }

    @Test
    void nothingReachesTheStreamBeforeFlush() throws Exception {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(wire);
        w.write(JsonNodeFactory.instance.objectNode().put("type", "pong"));
        assertThat(wire.size()).isZero();
        w.flush();
        assertThat(wire.toString(UTF_8)).isEqualTo("{\"type\":\"pong\"}\n");
    }

    @Test
    void batchesOfOneFrameAndOfSeveralReachTheStreamWholeAndInOrder() throws Exception {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        FrameWriter w = new FrameWriter(wire);
        EncodedFrame first = EncodedFrame.of(Frame.of(sampleHeader(1)));
        EncodedFrame image = EncodedFrame.of(new Frame(sampleHeader(2), new byte[] {7, 8}));
        EncodedFrame third = EncodedFrame.of(Frame.of(sampleHeader(3)));
        w.send(java.util.List.of(first));
        assertThat(wire.size()).isEqualTo(first.line().length);
        w.send(java.util.List.of(image, third));
        w.send(java.util.List.of(first));

        FrameReader r = new FrameReader(new ByteArrayInputStream(wire.toByteArray()), 1_024, 1_024);
        assertThat(r.read().header().path("seq").asInt()).isEqualTo(1);
        Frame withBody = r.read();
        assertThat(withBody.header().path("seq").asInt()).isEqualTo(2);
        assertThat(withBody.body()).containsExactly(7, 8);
        assertThat(r.read().header().path("seq").asInt()).isEqualTo(3);
        assertThat(r.read().header().path("seq").asInt()).isEqualTo(1);
        assertThat(r.read()).isNull();
    }

    private static ObjectNode sampleHeader(int seq) {
        return JsonNodeFactory.instance.objectNode().put("type", "sample").put("seq", seq);
    }
}
