package org.habla.net;

import static java.nio.charset.StandardCharsets.ISO_8859_1;
import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class LineFramerTest {

    private static LineFramer framer(String text, int max) {
        return new LineFramer(new ByteArrayInputStream(text.getBytes(UTF_8)), max);
    }

    private static String line(LineFramer f) throws Exception {
        byte[] b = f.readLine();
        return b == null ? null : new String(b, UTF_8);
    }

    @Test
    void linesAreReturnedWithoutTheirEndsAndNullAtCleanEof() throws Exception {
        LineFramer f = framer("one\ntwo\r\n\nthree\n", 100);
        assertThat(line(f)).isEqualTo("one");
        assertThat(line(f)).isEqualTo("two");
        assertThat(line(f)).isEqualTo("");
        assertThat(line(f)).isEqualTo("three");
        assertThat(line(f)).isNull();
    }

    @Test
    void splitReadsOfOneByteGiveTheSameLines() throws Exception {
        InputStream in = new TrickleInputStream("alpha\r\nbeta\n".getBytes(UTF_8));
        LineFramer f = new LineFramer(in, 100);
        assertThat(line(f)).isEqualTo("alpha");
        assertThat(line(f)).isEqualTo("beta");
        assertThat(line(f)).isNull();
    }

    @Test
    void anOverlongLineIsSkippedWithARecoverableErrorNamingTheLimit() throws Exception {
        LineFramer f = framer("x".repeat(50_000) + "\nnext\n", 16);
        assertThatThrownBy(f::readLine).isInstanceOfSatisfying(FrameException.class, e -> {
            assertThat(e.code()).isEqualTo("line_too_long");
            assertThat(e.fatal()).isFalse();
            assertThat(e.getMessage()).contains("maxLineBytes=16");
        });
        assertThat(line(f)).isEqualTo("next");
    }

    @Test
    void aLineOfExactlyTheLimitPassesWithOrWithoutCarriageReturn() throws Exception {
        LineFramer f = framer("abcd\nabcd\r\nabcde\nok\n", 4);
        assertThat(line(f)).isEqualTo("abcd");
        assertThat(line(f)).isEqualTo("abcd");
        assertThatThrownBy(f::readLine).hasFieldOrPropertyWithValue("code", "line_too_long");
        assertThat(line(f)).isEqualTo("ok");
    }

    @Test
    void endOfStreamInsideALineIsFatal() {
        LineFramer f = framer("{\"type\":", 100);
        assertThatThrownBy(f::readLine).isInstanceOfSatisfying(FrameException.class, e -> {
            assertThat(e.code()).isEqualTo("truncated");
            assertThat(e.fatal()).isTrue();
        });
    }

    @Test
    void rawBytesAfterALineComeFromTheSameBuffer() throws Exception {
        LineFramer f = framer("head\nBODYtail\n", 100);
        assertThat(line(f)).isEqualTo("head");
        assertThat(new String(f.readBytes(4), UTF_8)).isEqualTo("BODY");
        assertThat(line(f)).isEqualTo("tail");
        assertThatThrownBy(() -> f.readBytes(1)).isInstanceOf(EOFException.class);
    }

    @Test
    void eachOverlongLineIsReportedOnceAndTheLinesAroundItStillArrive() throws Exception {
        LineFramer f = framer("12345678\n123456789\n" + "x".repeat(10_000) + "\nok\n", 8);
        List<String> lines = new ArrayList<>();
        int tooLong = 0;
        for (int i = 0; i < 10; i++) {
            try {
                String l = line(f);
                if (l == null) {
                    break;
                }
                lines.add(l);
            } catch (FrameException e) {
                assertThat(e.code()).isEqualTo("line_too_long");
                tooLong++;
            }
        }
        assertThat(lines).containsExactly("12345678", "ok");
        assertThat(tooLong).isEqualTo(2);
    }

    @Test
    void theStreamEndingInsideAnOverlongLineIsFatalAndNamesTheLimit() throws Exception {
        LineFramer f = new LineFramer(new TrickleInputStream(("ok\n" + "y".repeat(300)).getBytes(UTF_8)), 100);
        assertThat(line(f)).isEqualTo("ok");
        assertThatThrownBy(f::readLine).isInstanceOfSatisfying(FrameException.class, e -> {
            assertThat(e.code()).isEqualTo("line_too_long");
            assertThat(e.fatal()).isTrue();
            assertThat(e.getMessage()).contains("maxLineBytes=100");
        });
    }

    @Test
    void aLimitOfOneByteAllowsOneByteLines() throws Exception {
        LineFramer f = framer("a\r\nbc\nd\n", 1);
        assertThat(line(f)).isEqualTo("a");
        assertThatThrownBy(f::readLine).hasFieldOrPropertyWithValue("code", "line_too_long");
        assertThat(line(f)).isEqualTo("d");
        assertThatThrownBy(() -> new LineFramer(InputStream.nullInputStream(), 0))
                .hasMessageContaining("maxLineBytes");
    }

    @Test
    void textComesOutInTheCharsetAsked() throws Exception {
        byte[] bytes = {'c', 'a', 'f', (byte) 0xE9, '\r', '\n'};
        LineFramer f = new LineFramer(new ByteArrayInputStream(bytes), 10);
        assertThat(f.readText(ISO_8859_1)).isEqualTo("café");
        assertThat(f.readText(ISO_8859_1)).isNull();
    }

    @Test
    void aFramerKeepingCarriageReturnsHandsThemOutAndCountsThemInTheLimit() throws Exception {
        LineFramer f = LineFramer.keepingCarriageReturns(
                new ByteArrayInputStream("stop\r\nstop\nhalt\r\n".getBytes(UTF_8)), 4);
        assertThatThrownBy(f::readLine).isInstanceOfSatisfying(FrameException.class, e -> {
            assertThat(e.code()).isEqualTo("line_too_long");
            assertThat(e.fatal()).isFalse();
        });
        assertThat(line(f)).isEqualTo("stop");
        assertThatThrownBy(f::readLine).hasFieldOrPropertyWithValue("code", "line_too_long");

        LineFramer wide = LineFramer.keepingCarriageReturns(
                new TrickleInputStream("stop\r\nstop\n".getBytes(UTF_8)), 5);
        assertThat(line(wide)).isEqualTo("stop\r");
        assertThat(line(wide)).isEqualTo("stop");
        assertThat(line(wide)).isNull();
    }

    @Test
    void thePositionCountsTheBytesOfEveryLineBlockAndSkippedLineHandedOut() throws Exception {
        byte[] bytes = ("one\r\n" + "x".repeat(40) + "\nhead\nBODY" + "two\n").getBytes(UTF_8);
        // Read ahead into the framer's buffer at once, and one byte per read (a block then comes straight in).
        positionsOf(new LineFramer(new ByteArrayInputStream(bytes), 8));
        positionsOf(new LineFramer(new TrickleInputStream(bytes), 8));
    }

    private static void positionsOf(LineFramer f) throws Exception {
        assertThat(f.position()).isZero();
        assertThat(line(f)).isEqualTo("one");
        assertThat(f.position()).isEqualTo(5);
        assertThatThrownBy(f::readLine).hasFieldOrPropertyWithValue("code", "line_too_long");
        assertThat(f.position()).isEqualTo(46);
        assertThat(line(f)).isEqualTo("head");
        assertThat(f.readBytes(4)).hasSize(4);
        assertThat(f.position()).isEqualTo(55);
        assertThat(line(f)).isEqualTo("two");
        assertThat(f.position()).isEqualTo(59);
    }
}
