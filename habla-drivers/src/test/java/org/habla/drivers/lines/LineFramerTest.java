package org.habla.drivers.lines;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class LineFramerTest {

    private final List<String> lines = new ArrayList<>();
    private int overlong;
    private final LineFramer.Listener listener = new LineFramer.Listener() {
        @Override
        public void line(byte[] bytes) {
            lines.add(new String(bytes, StandardCharsets.UTF_8));
        }

        @Override
        public void overlong(int maxLineBytes) {
            overlong++;
        }
    };

    private void push(LineFramer f, String text) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        f.push(b, 0, b.length, listener);
    }

    @Test
    void linesEndAtNewlineWithATrailingCarriageReturnStripped() {
        LineFramer f = new LineFramer(100);
        push(f, "1\n-0.5\r\n\nhalf");
        assertThat(lines).containsExactly("1", "-0.5", "");
        assertThat(f.pending()).isEqualTo(4);
        push(f, " line\n");
        assertThat(lines).containsExactly("1", "-0.5", "", "half line");
    }

    @Test
    void aLineSplitIntoSingleBytesComesOutWhole() {
        LineFramer f = new LineFramer(100);
        for (char c : "forward\r\nback\n".toCharArray()) {
            push(f, String.valueOf(c));
        }
        assertThat(lines).containsExactly("forward", "back");
    }

    @Test
    void anOverlongLineIsDroppedOnceAndTheStreamGoesOn() {
        LineFramer f = new LineFramer(8);
        push(f, "12345678\n123456789\n" + "x".repeat(10_000) + "\nok\n");
        assertThat(lines).containsExactly("12345678", "ok");
        assertThat(overlong).isEqualTo(2);
        assertThat(f.pending()).isZero();
    }

    @Test
    void aCarriageReturnDoesNotCountAgainstTheLimit() {
        LineFramer f = new LineFramer(4);
        push(f, "abcd\r\nabcde\r\n");
        assertThat(lines).containsExactly("abcd");
        assertThat(overlong).isEqualTo(1);
    }
}
