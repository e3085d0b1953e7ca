package org.habla.drivers.pcm;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import org.habla.drivers.pioneer.RecordingSink;
import org.habla.sample.AudioChunk;
import org.habla.sample.Payload;
import org.junit.jupiter.api.Test;

class PcmStreamSessionTest {

    private final RecordingSink sink = new RecordingSink();

    /** {@code frames} frames of a 440 Hz tone, 16-bit little-endian, the same sample on every channel. */
    private static byte[] tone(int rateHz, int channels, int frames) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i < frames; i++) {
            short s = (short) Math.round(12_000 * Math.sin(2 * Math.PI * 440 * i / rateHz));
            for (int c = 0; c < channels; c++) {
                out.write(s & 0xFF);
                out.write((s >>> 8) & 0xFF);
            }
        }
        return out.toByteArray();
    }

    @Test
    void aMonoStreamComesOutAsHundredMillisecondChunksByteForByte() throws Exception {
        byte[] pcm = tone(16_000, 1, 16_000);
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(pcm, 4_096);
            PcmStreamSession session = new PcmStreamSession(PcmStreamParams.defaults());
            for (int i = 0; i < 10; i++) {
                session.readNext(peer.driverIn(), sink);
            }
        }
        ByteArrayOutputStream joined = new ByteArrayOutputStream();
        for (Payload p : sink.on("audio")) {
            AudioChunk chunk = (AudioChunk) p;
            assertThat(chunk.frameCount()).isEqualTo(1_600);
            assertThat(chunk.format().sampleRateHz()).isEqualTo(16_000);
            joined.writeBytes(chunk.pcm());
        }
        assertThat(sink.on("audio")).hasSize(10);
        assertThat(joined.toByteArray()).isEqualTo(pcm);
        double[] samples = ((AudioChunk) sink.on("audio").get(0)).channel(0);
        assertThat(samples[4]).isCloseTo(12_000 * Math.sin(2 * Math.PI * 440 * 4 / 16_000.0) / 32768, within(1e-4));
    }

    @Test
    void writesThatSplitFramesStillGiveWholeFramesInOrder() throws Exception {
        PcmStreamParams stereo = new PcmStreamParams(8_000, 2, 16, 10);
        byte[] pcm = tone(8_000, 2, 800);
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(pcm, 7);
            PcmStreamSession session = new PcmStreamSession(stereo);
            for (int i = 0; i < 10; i++) {
                session.readNext(peer.driverIn(), sink);
            }
        }
        ByteArrayOutputStream joined = new ByteArrayOutputStream();
        for (Payload p : sink.on("audio")) {
            assertThat(((AudioChunk) p).frameCount()).isEqualTo(80);
            assertThat(((AudioChunk) p).format().channels()).isEqualTo(2);
            joined.writeBytes(((AudioChunk) p).pcm());
        }
        assertThat(joined.toByteArray()).isEqualTo(pcm);
    }

    @Test
    void theEndOfTheStreamEmitsTheWholeFramesLeftAndReportsAHalfFrame() throws Exception {
        byte[] pcm = tone(16_000, 1, 100);
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(pcm, pcm.length);
            peer.deviceWrites(new byte[] {0x11}, 1);
            peer.deviceHangsUp();
            PcmStreamSession session = new PcmStreamSession(PcmStreamParams.defaults());
            assertThatThrownBy(() -> session.readNext(peer.driverIn(), sink)).isInstanceOf(EOFException.class);
        }
        assertThat(((AudioChunk) sink.last("audio")).pcm()).isEqualTo(pcm);
        assertThat(sink.malformed()).singleElement().asString().contains("1 byte(s) dropped");
    }

    @Test
    void chunksCarryTheTimeTheirFirstFrameWasCaptured() throws Exception {
        long[] source = new long[1];
        org.habla.driver.ReadingSink timing = new org.habla.driver.ReadingSink() {
            @Override
            public Channel channel(String name) {
                return Channel.of(value -> reading(name, value), (value, micros) -> reading(name, value, micros));
            }

            @Override
            public void reading(String channel, Payload value) {
                throw new AssertionError("audio must carry its source time");
            }

            @Override
            public void reading(String channel, Payload value, long sourceMicros) {
                source[0] = sourceMicros;
            }

            @Override
            public void malformed(String what) {
            }

            @Override
            public void robotInfo(com.fasterxml.jackson.databind.node.ObjectNode info) {
            }
        };
        try (LoopbackPeer peer = new LoopbackPeer()) {
            peer.deviceWrites(tone(16_000, 1, 1_600), 3_200);
            long before = System.currentTimeMillis() * 1_000L;
            new PcmStreamSession(PcmStreamParams.defaults()).readNext(peer.driverIn(), timing);
            long after = System.currentTimeMillis() * 1_000L;
            assertThat(source[0]).isBetween(before - 100_000, after - 100_000);
        }
    }
}
