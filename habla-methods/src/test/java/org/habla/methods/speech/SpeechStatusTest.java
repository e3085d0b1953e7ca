package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class SpeechStatusTest {

    @Test
    void theLineSaysWhereTheChainStopsHearing() {
        SpeechStatus s = new SpeechStatus("moonshine");
        assertThat(s.line(-1, 0)).isEqualTo("moonshine: 0 utterances cut, 0 decoded, 0 said; rejected: 0 without voice, "
                + "0 no phrase, 0 low confidence; no utterance open; 0 queued; dropped: 0 over maxPending, 0 waited over 5 s; "
                + "no decoding yet");
        s.cut = 5;
        s.unvoiced = 1;
        s.decoded = 4;
        s.lowConfidence = 1;
        s.said = 3;
        s.dropped = 2;
        s.late = 1;
        for (long ms : new long[] {100, 120, 140, 900}) {
            s.decodeTook(ms);
        }
        assertThat(s.line(1240, 3)).isEqualTo("moonshine: 5 utterances cut, 4 decoded, 3 said; rejected: 1 without "
                + "voice, 0 no phrase, 1 low confidence; utterance open 1.2 s; 3 queued; dropped: 2 over maxPending, 1 waited "
                + "over 5 s; decoding p50 120 ms, p99 900 ms");
    }

    @Test
    void thePercentilesCoverTheLastWindowOfDecodings() {
        SpeechStatus s = new SpeechStatus("sphinx4");
        for (int i = 0; i < SpeechStatus.WINDOW; i++) {
            s.decodeTook(1000);
        }
        for (int i = 0; i < SpeechStatus.WINDOW; i++) {
            s.decodeTook(10);
        }
        assertThat(s.decodePercentile(0.99)).isEqualTo(10);
    }
}
