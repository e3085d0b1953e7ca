package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class FrameReaderTest {

    private static FrameReader reader(byte[] bytes) {
        return new FrameReader(new ByteArrayInputStream(bytes), 1_024, 4_096);
    }

    private static FrameReader reader(String text) {
        return reader(text.getBytes(UTF_8));
    }

    private static FrameException errorOf(FrameReader r) {
        try {
            r.read();
        } catch (FrameException e) {
            return e;
        } catch (Exception e) {
            throw new AssertionError("expected a FrameException, got " + e);
        }
        throw new AssertionError("expected a FrameException, got a frame");
    }

    @Test
    void aHeaderOnlyFrameIsReadAndBlankLinesAreSkipped() throws Exception {
        FrameReader r = reader("\n  \r\n{\"op\":\"ping\",\"id\":3}\n");
        Frame f = r.read();
        assertThat(f.header().path("op").asText()).isEqualTo("ping");
        assertThat(f.header().path("id").asInt()).isEqualTo(3);
        assertThat(f.body()).isEmpty();
        assertThat(f.hasBody()).isFalse();
        assertThat(r.read()).isNull();
    }

    @Test
    void aBinaryTrailerIsReadEvenWhenItContainsNewlines() throws Exception {
        byte[] body = {'\n', 0, (byte) 0xff, '\n', 'x'};
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        wire.write("{\"kind\":\"image\",\"bytes\":5}\n".getBytes(UTF_8));
        wire.write(body);
        wire.write("{\"op\":\"ping\"}\n".getBytes(UTF_8));
        FrameReader r = new FrameReader(new TrickleInputStream(wire.toByteArray()), 1_024, 4_096);
        Frame f = r.read();
        assertThat(f.body()).containsExactly(body);
        assertThat(r.read().header().path("op").asText()).isEqualTo("ping");
        assertThat(r.read()).isNull();
    }

    @Test
    void zeroBytesIsAnEmptyBody() throws Exception {
        Frame f = reader("{\"bytes\":0}\n").read();
        assertThat(f.hasBody()).isTrue();
        assertThat(f.body()).isEmpty();
    }

    @Test
    void invalidUtf8IsReportedAndTheNextFrameStillReads() throws Exception {
        ByteArrayOutputStream wire = new ByteArrayOutputStream();
        wire.write(new byte[] {'{', '"', 'a', '"', ':', '"', (byte) 0xc3, (byte) 0x28, '"', '}', '\n'});
        wire.write("{\"a\":\"ñ\"}\n".getBytes(UTF_8));
        FrameReader r = reader(wire.toByteArray());
        assertThat(errorOf(r).code()).isEqualTo("bad_utf8");
        assertThat(r.read().header().path("a").asText()).isEqualTo("ñ");
    }

    @Test
    void badJsonNonObjectsAndBadCountsAreRecoverable() throws Exception {
        FrameReader r = reader("{\"a\":\n[1,2]\n\"text\"\n{\"a\":1} {\"b\":2}\n{\"a\":1,\"a\":2}\n"
                + "{\"bytes\":-1}\n{\"bytes\":\"3\"}\n{\"bytes\":1.5}\n{\"ok\":true}\n");
        List<String> codes = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            FrameException e = errorOf(r);
            assertThat(e.fatal()).isFalse();
            codes.add(e.code());
        }
        assertThat(codes).containsExactly("bad_json", "not_object", "not_object", "bad_json", "bad_json",
                "bad_bytes", "bad_bytes", "bad_bytes");
        assertThat(r.read().header().path("ok").asBoolean()).isTrue();
    }

    @Test
    void aCountOverTheLimitIsFatalAndNamesTheLimit() {
        FrameException e = errorOf(reader("{\"bytes\":4097}\n"));
        assertThat(e.code()).isEqualTo("binary_too_large");
        assertThat(e.fatal()).isTrue();
        assertThat(e.getMessage()).contains("maxBinaryBytes=4096");
        assertThat(errorOf(reader("{\"bytes\":99999999999999999999}\n")).code()).isEqualTo("bad_bytes");
    }

    @Test
    void endOfStreamInsideTheBinaryBlockIsFatal() {
        FrameException e = errorOf(reader("{\"bytes\":10}\nabc"));
        assertThat(e.code()).isEqualTo("truncated");
        assertThat(e.fatal()).isTrue();
    }

    @Test
    void anOverlongLineIsReportedAndReadingGoesOn() throws Exception {
        FrameReader r = reader("{\"pad\":\"" + "y".repeat(5_000) + "\"}\n{\"n\":2}\n");
        assertThat(errorOf(r).code()).isEqualTo("line_too_long");
        assertThat(r.read().header().path("n").asInt()).isEqualTo(2);
    }

    @Test
    void garbageNeverEscapesAsAnythingButFrameErrors() throws Exception {
        Random random = new Random(42);
        byte[] garbage = new byte[200_000];
        random.nextBytes(garbage);
        FrameReader r = new FrameReader(new ByteArrayInputStream(garbage), 512, 1_024);
        int errors = 0;
        int frames = 0;
        for (int i = 0; i < 100_000; i++) {
            try {
                if (r.read() == null) {
                    break;
                }
                frames++;
            } catch (FrameException e) {
                errors++;
                if (e.fatal()) {
                    break;
                }
            }
        }
        assertThat(errors).isPositive();
        assertThat(frames).isZero();
    }
}
