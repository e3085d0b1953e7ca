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
}
