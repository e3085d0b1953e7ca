package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class WorldStateSessionTest {

    private final WorldStateSession session = new WorldStateSession();
    private final RecordingSink sink = new RecordingSink();

    @Test
    void anErs7PacketIs374Bytes() {
        assertThat(TekkotsuPackets.ers7WorldState()).hasSize(374);
        assertThat(Ers7.WORLD_STATE_BYTES).isEqualTo(374);
    }

    @Test
    void everyFieldOfAnErs7PacketLandsOnItsChannel() throws IOException {
        session.readNext(new ByteArrayInputStream(TekkotsuPackets.ers7WorldState()), sink);

        assertThat(sink.malformed).isEmpty();
        float[] outputs = TekkotsuPackets.ers7Outputs();
        double[] joints = ((VectorValue) sink.on("joints").get(0)).toArray();
        assertThat(joints).hasSize(18);
        for (int i = 0; i < 18; i++) {
            assertThat(joints[i]).isEqualTo((double) outputs[i]);
        }
        RecordValue head = (RecordValue) sink.on("head-pose").get(0);
        assertThat(head.number("tiltRad")).isEqualTo((double) outputs[12]);
        assertThat(head.number("panRad")).isEqualTo((double) outputs[13]);
        assertThat(head.number("nodRad")).isEqualTo((double) outputs[14]);
        assertThat(((VectorValue) sink.on("ir").get(0)).toArray()).containsExactly(0.234, 0.876, 0.432);
        assertThat(((VectorValue) sink.on("accel").get(0)).toArray()).containsExactly(-0.5, 1.25, -9.75);
        RecordValue buttons = (RecordValue) sink.on("buttons").get(0);
        assertThat(buttons.number("leftFrontPaw")).isEqualTo(1.0);
        assertThat(buttons.number("rightFrontPaw")).isEqualTo(0.0);
        assertThat(buttons.number("leftBackPaw")).isEqualTo(1.0);
        assertThat(buttons.number("rightBackPaw")).isEqualTo(0.0);
        assertThat(buttons.number("chin")).isEqualTo(1.0);
        assertThat(buttons.number("headTouch")).isEqualTo(0.5);
        assertThat(buttons.number("backFront")).isEqualTo(0.25);
        assertThat(buttons.number("backMiddle")).isEqualTo(0.75);
        assertThat(buttons.number("backRear")).as("clamped to 1").isEqualTo(1.0);
        assertThat(buttons.number("wirelessSwitch")).as("clamped to 1").isEqualTo(1.0);
        assertThat(sink.info).hasSize(1);
        assertThat(sink.info.get(0).get("model").asText()).isEqualTo("ERS-7");
        assertThat(sink.info.get(0).get("batteryPercent").asLong()).isEqualTo(80);
        assertThat(sink.info.get(0).get("batteryVoltageV").asDouble()).isEqualTo((double) 8.2f);
    }

    @Test
    void theHeadPoseAndButtonRecordsAreWrittenAsTheDriverDocumentsThem() throws IOException {
        float[] outputs = new float[Ers7.NUM_OUTPUTS];
        outputs[Ers7.HEAD_TILT] = -0.5f;
        outputs[Ers7.HEAD_PAN] = 0.25f;
        outputs[Ers7.HEAD_NOD] = 0.125f;
        session.readNext(new ByteArrayInputStream(TekkotsuPackets.worldState("ERS-7", outputs,
                TekkotsuPackets.ers7Sensors(), TekkotsuPackets.ers7Buttons(), new float[Ers7.NUM_PID_JOINTS])), sink);

        assertThat(((RecordValue) sink.on("head-pose").get(0)).jsonView().toString())
                .isEqualTo("{\"tiltRad\":-0.5,\"panRad\":0.25,\"nodRad\":0.125}");
        assertThat(((RecordValue) sink.on("buttons").get(0)).jsonView().toString()).isEqualTo("{\"leftFrontPaw\":1.0,"
                + "\"rightFrontPaw\":0.0,\"leftBackPaw\":1.0,\"rightBackPaw\":0.0,\"chin\":1.0,\"headTouch\":0.5,"
                + "\"backFront\":0.25,\"backMiddle\":0.75,\"backRear\":1.0,\"wirelessSwitch\":1.0}");
        assertThat(((RecordValue) sink.on("head-pose").get(0)).form(HeadPoseReading.class)).as("typed inside the daemon")
                .contains(new HeadPoseReading(-0.5, 0.25, 0.125));
        assertThat(((RecordValue) sink.on("buttons").get(0)).form(ButtonsReading.class)).isPresent();
    }

    @Test
    void packetsSplitIntoSingleBytesDecodeTheSame() throws IOException {
        byte[] two = concat(TekkotsuPackets.ers7WorldState(), TekkotsuPackets.ers7WorldState());
        InputStream in = new OneByteAtATime(two);
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.on("ir")).hasSize(2).allSatisfy(v ->
                assertThat(((VectorValue) v).toArray()).containsExactly(0.234, 0.876, 0.432));
        assertThat(sink.malformed).isEmpty();
        assertThat(sink.info).as("the status is told once while nothing changes").hasSize(1);
    }

    @Test
    void aPacketCutShortEndsTheLinkNamingTheField() {
        byte[] packet = TekkotsuPackets.ers7WorldState();
        InputStream in = new ByteArrayInputStream(Arrays.copyOf(packet, 230));

        assertThatThrownBy(() -> session.readNext(in, sink)).isInstanceOf(EOFException.class)
                .hasMessageContaining("sensors");
    }

    @Test
    void garbageIsReportedOnceAndTheNextPacketIsFound() throws IOException {
        byte[] garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 'E', 'R', 'S', 11};
        InputStream in = new ByteArrayInputStream(concat(TekkotsuPackets.ers7WorldState(), garbage,
                TekkotsuPackets.ers7WorldState()));
        session.readNext(in, sink);
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("out of step");
        assertThat(sink.on("joints")).hasSize(2);
    }

    @Test
    void theOldPre40LayoutEndsTheLinkSayingSo() {
        byte[] old = TekkotsuPackets.start().u32(5_000).u32(18).build();

        assertThatThrownBy(() -> session.readNext(new ByteArrayInputStream(old), sink))
                .isInstanceOf(IOException.class).hasMessageContaining("pre-4.0");
    }

    @Test
    void anErs210PacketIsReportedAndSkippedAndTheNextErs7PacketDecoded() throws IOException {
        byte[] ers210 = TekkotsuPackets.worldState("ERS-210", new float[29], new float[10], new float[8],
                new float[18]);
        assertThat(ers210).hasSize(292);
        InputStream in = new ByteArrayInputStream(concat(ers210, TekkotsuPackets.ers7WorldState()));
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("ERS-210").contains("ERS-7 layout only");
        assertThat(sink.on("joints")).hasSize(1);
    }

    @Test
    void anErs7PacketWithCountsThatDoNotMatchTheTablesIsReported() throws IOException {
        byte[] odd = TekkotsuPackets.worldState("ERS-7", new float[47], new float[8], new float[6], new float[18]);
        session.readNext(new ByteArrayInputStream(odd), sink);

        assertThat(sink.malformed).hasSize(1).first().asString()
                .contains("8 sensors (expected 11)").contains("6 buttons (expected 10)");
        assertThat(sink.readings).isEmpty();
    }

    @Test
    void anAbsurdCountIsReportedAndTheStreamResynchronises() throws IOException {
        byte[] bad = TekkotsuPackets.start().cString("ERS-7").u32(1).u32(2).u32(1_000_000).build();
        InputStream in = new ByteArrayInputStream(concat(bad, TekkotsuPackets.ers7WorldState()));
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("number of outputs is 1000000");
        assertThat(sink.on("buttons")).hasSize(1);
    }

    @Test
    void aModelNameThatIsNotTextIsReported() throws IOException {
        byte[] bad = TekkotsuPackets.start().ascii("ERS-").u8(0x01).build();
        InputStream in = new ByteArrayInputStream(concat(bad, TekkotsuPackets.ers7WorldState()));
        session.readNext(in, sink);
        session.readNext(in, sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("model name");
        assertThat(sink.on("head-pose")).hasSize(1);
    }

    @Test
    void aStreamWithNoPacketStartEndsTheLink() {
        byte[] noise = new byte[WorldStateSession.RESYNC_LIMIT_BYTES + 100];
        Arrays.fill(noise, (byte) 7);
        InputStream in = new ByteArrayInputStream(concat(TekkotsuPackets.ers7WorldState(), noise));

        assertThatThrownBy(() -> {
            for (int i = 0; i < 3; i++) {
                session.readNext(in, sink);
            }
        }).isInstanceOf(IOException.class).hasMessageContaining("no start of World State packet");
    }

    static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }
}
