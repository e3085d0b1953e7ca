package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class ArcosPacketDecoderTest {

    private final ArcosPacketDecoder decoder = new ArcosPacketDecoder();
    private final List<ArcosPacket> packets = new ArrayList<>();
    private final List<String> malformed = new ArrayList<>();
    private final ArcosPacketDecoder.Listener listener = new ArcosPacketDecoder.Listener() {
        @Override
        public void packet(ArcosPacket packet) {
            packets.add(packet);
        }

        @Override
        public void malformed(String what) {
            malformed.add(what);
        }
    };

    private void push(byte[] bytes) {
        decoder.push(bytes, listener);
    }

    private static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    private static final byte[] PULSE = ArcosCommand.PULSE.packet().toWire();
    private static final byte[] VEL = ArcosCommand.VEL.packet(300).toWire();

    @Test
    void theCapturedSipComesOutWholeWithItsChecksumAccepted() {
        push(CapturedSip.wire());
        assertThat(packets).hasSize(1);
        assertThat(packets.get(0).type()).isEqualTo(0x32);
        assertThat(packets.get(0).payloadLength()).isEqualTo(83);
        assertThat(malformed).isEmpty();
        assertThat(decoder.pending()).isZero();
    }

    @Test
    void aStreamSplitIntoOneByteReadsYieldsTheSamePackets() {
        byte[] stream = concat(PULSE, CapturedSip.wire(), VEL, CapturedSip.wire());
        for (byte b : stream) {
            push(new byte[] {b});
        }
        assertThat(packets).extracting(ArcosPacket::type).containsExactly(0x00, 0x32, 0x0B, 0x32);
        assertThat(malformed).isEmpty();
    }

    @Test
    void aWrongChecksumDropsThePacketAndTheNextOneStillArrives() {
        byte[] bad = CapturedSip.wire();
        bad[bad.length - 1] ^= 0x01;
        push(concat(bad, VEL));
        assertThat(packets).containsExactly(ArcosCommand.VEL.packet(300));
        assertThat(malformed).hasSize(1);
        assertThat(malformed.get(0)).contains("checksum 0x5C9A").contains("0x5C9B");
    }

    @Test
    void aCorruptedDataByteIsCaughtByTheChecksum() {
        byte[] bad = CapturedSip.wire();
        bad[20] ^= 0x10;
        push(concat(bad, PULSE));
        assertThat(packets).containsExactly(ArcosCommand.PULSE.packet());
        assertThat(malformed).singleElement().asString().contains("checksum");
    }

    @Test
    void aTruncatedPacketFollowedByAGoodOneLosesOnlyTheTruncatedOne() {
        byte[] sip = CapturedSip.wire();
        byte[] truncated = java.util.Arrays.copyOf(sip, 40);
        push(concat(truncated, sip, VEL));
        // the truncated packet's count swallows the start of the next SIP, the checksum fails, and the
        // decoder hunts again inside the bytes it had taken: the whole SIP behind is recovered
        assertThat(packets).extracting(ArcosPacket::type).containsExactly(0x32, 0x0B);
        assertThat(malformed).hasSize(1);
    }

    @Test
    void garbageAfterABadPacketIsReportedApartFromIt() {
        byte[] bad = CapturedSip.wire();
        bad[10] ^= 0x01;
        push(concat(bad, Hex.bytes("01 02 03"), PULSE));
        assertThat(packets).containsExactly(ArcosCommand.PULSE.packet());
        assertThat(malformed).hasSize(2);
        assertThat(malformed.get(1)).contains("3 byte(s) of garbage");
    }

    @Test
    void aByteCountOverTwoHundredIsRejectedWithoutSwallowingWhatFollows() {
        push(concat(Hex.bytes("FA FB C9 32 00 00"), PULSE));
        assertThat(packets).containsExactly(ArcosCommand.PULSE.packet());
        assertThat(malformed).singleElement().asString().contains("byte count 201").contains("3..200");
    }

    @Test
    void aByteCountTooSmallForAChecksumIsRejected() {
        push(concat(Hex.bytes("FA FB 02 00 00"), VEL));
        assertThat(packets).containsExactly(ArcosCommand.VEL.packet(300));
        assertThat(malformed).singleElement().asString().contains("byte count 2");
    }

    @Test
    void garbageBetweenPacketsIsSkippedAndReportedOnce() {
        push(concat(PULSE, Hex.bytes("00 13 FA 77 FB 42 FA"), VEL));
        assertThat(packets).containsExactly(ArcosCommand.PULSE.packet(), ArcosCommand.VEL.packet(300));
        assertThat(malformed).singleElement().asString().contains("7 byte(s) of garbage");
    }

    @Test
    void aPacketThatIsNotYetCompleteWaitsForItsLastByte() {
        byte[] sip = CapturedSip.wire();
        decoder.push(sip, 0, sip.length - 1, listener);
        assertThat(packets).isEmpty();
        assertThat(decoder.pending()).isEqualTo(sip.length - 1);
        decoder.push(sip, sip.length - 1, 1, listener);
        assertThat(packets).hasSize(1);
    }

    @Test
    void syncIsNeverLostForGoodWhateverNoiseComesFirst() {
        Random random = new Random(20261122L);
        for (int round = 0; round < 200; round++) {
            byte[] noise = new byte[random.nextInt(600)];
            random.nextBytes(noise);
            if (round % 3 == 0 && noise.length > 3) {
                noise[noise.length - 3] = (byte) 0xFA;
                noise[noise.length - 2] = (byte) 0xFB;
                noise[noise.length - 1] = (byte) 0xC8;
            }
            packets.clear();
            push(noise);
            // a noise header may claim up to 200 bytes; enough good packets behind it always get through
            for (int i = 0; i < 40; i++) {
                push(VEL);
            }
            assertThat(packets).as("round %d", round).contains(ArcosCommand.VEL.packet(300));
            assertThat(packets.get(packets.size() - 1)).isEqualTo(ArcosCommand.VEL.packet(300));
        }
        assertThat(decoder.dropped()).isPositive();
    }

    @Test
    void moreBytesThanTheBufferHoldsInOnePushAreAllDecoded() {
        ByteArrayOutputStream big = new ByteArrayOutputStream();
        for (int i = 0; i < 50; i++) {
            big.writeBytes(CapturedSip.wire());
        }
        push(big.toByteArray());
        assertThat(packets).hasSize(50);
        assertThat(decoder.packets()).isEqualTo(50);
        assertThat(malformed).isEmpty();
    }
}
