package org.habla.drivers.tekkotsu;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.habla.sample.ImageFrame;
import org.junit.jupiter.api.Test;

class RawCamSessionTest {

    private final RawCamSession session = new RawCamSession();
    private final RecordingSink sink = new RecordingSink();

    static byte[] jpeg(int width, int height, int type) throws IOException {
        BufferedImage image = new BufferedImage(width, height, type);
        var g = image.createGraphics();
        g.setColor(new Color(230, 80, 160));
        g.fillOval(width / 4, height / 4, width / 2, height / 2);
        g.dispose();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertThat(ImageIO.write(image, "jpg", out)).isTrue();
        return out.toByteArray();
    }

    /** The default raw-camera packet: colour, JPEG, one JPEGColor section at the 104 × 80 layer. */
    static byte[] jpegColourPacket(byte[] jpeg, long frame) {
        return TekkotsuPackets.cameraHeader(0, 1, 104, 80, frame).section(104, 80, 3, 0, "JPEGColor")
                .u32(jpeg.length).bytes(jpeg).build();
    }

    @Test
    void theHeaderIs42Bytes() {
        assertThat(TekkotsuPackets.cameraHeader(0, 1, 104, 80, 1).build()).hasSize(42);
        assertThat(CameraPacket.MAGIC).hasSize(18);
    }

    @Test
    void aJpegColourPacketBecomesAJpegFrameOfTheHeadersSize() throws IOException {
        byte[] jpeg = jpeg(104, 80, BufferedImage.TYPE_INT_RGB);
        session.readNext(new ByteArrayInputStream(jpegColourPacket(jpeg, 7)), sink);

        ImageFrame frame = (ImageFrame) sink.on("camera").get(0);
        assertThat(frame.encoding()).isEqualTo("jpeg");
        assertThat(frame.width()).isEqualTo(104);
        assertThat(frame.height()).isEqualTo(80);
        assertThat(frame.data()).isEqualTo(jpeg);
        BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(frame.data()));
        assertThat(decoded.getWidth()).isEqualTo(104);
        assertThat(sink.malformed).isEmpty();
    }

    @Test
    void aGreyscaleJpegPacketIsOneSection() throws IOException {
        byte[] jpeg = jpeg(52, 40, BufferedImage.TYPE_BYTE_GRAY);
        byte[] packet = TekkotsuPackets.cameraHeader(1, 1, 52, 40, 1).section(52, 40, 2, 0, "JPEGGrayscale")
                .u32(jpeg.length).bytes(jpeg).build();
        session.readNext(new ByteArrayInputStream(packet), sink);

        ImageFrame frame = (ImageFrame) sink.on("camera").get(0);
        assertThat(frame.encoding()).isEqualTo("jpeg");
        assertThat(frame.data()).isEqualTo(jpeg);
    }

    @Test
    void uncompressedYuvSectionsBecomeBgrWithUpsampledChroma() throws IOException {
        byte[] y = {(byte) 128, (byte) 128, 50, 50, (byte) 200, (byte) 200, 0, 0};
        byte[] u = {(byte) 128, (byte) 228};
        byte[] v = {(byte) 228, (byte) 128};
        byte[] packet = TekkotsuPackets.cameraHeader(0, 0, 4, 2, 1)
                .section(4, 2, 3, 0, "RawImage").bytes(y)
                .section(2, 1, 2, 1, "RawImage").bytes(u)
                .section(2, 1, 2, 2, "RawImage").bytes(v).build();
        session.readNext(new ByteArrayInputStream(packet), sink);

        ImageFrame frame = (ImageFrame) sink.on("camera").get(0);
        assertThat(frame.encoding()).isEqualTo("bgr8");
        assertThat(frame.width()).isEqualTo(4);
        assertThat(frame.height()).isEqualTo(2);
        byte[] bgr = frame.data();
        // pixel (0,0): Y 128, Cb 0, Cr +100 -> B 128, G 128 - 71.4 = 57, R 128 + 140.2 = 255 (clamped)
        assertThat(Arrays.copyOfRange(bgr, 0, 3)).containsExactly(128, 57, 255);
        // pixel (2,0): Y 50, Cb +100, Cr 0 -> B 50 + 177.2 = 227, G 50 - 34.4 = 16, R 50
        assertThat(Arrays.copyOfRange(bgr, 6, 9)).containsExactly(227, 16, 50);
        // pixel (3,1): Y 0 under the same chroma -> B 177, G 0 (clamped), R 0
        assertThat(Arrays.copyOfRange(bgr, 21, 24)).containsExactly(177, 0, 0);
    }

    @Test
    void aSingleUncompressedChannelBecomesGrey() throws IOException {
        byte[] packet = TekkotsuPackets.cameraHeader(1, 0, 3, 1, 1).section(3, 1, 3, 0, "RawImage")
                .bytes(new byte[] {1, 2, 3}).build();
        session.readNext(new ByteArrayInputStream(packet), sink);

        ImageFrame frame = (ImageFrame) sink.on("camera").get(0);
        assertThat(frame.encoding()).isEqualTo("gray8");
        assertThat(frame.data()).containsExactly(1, 2, 3);
    }

    @Test
    void closeConnectionAndSensorStringsAreSkipped() throws IOException {
        byte[] jpeg = jpeg(104, 80, BufferedImage.TYPE_INT_RGB);
        InputStream in = new ByteArrayInputStream(WorldStateSessionTest.concat(
                TekkotsuPackets.start().loadSave("#POS\ncondensed ERS-7\n#END\n").build(),
                TekkotsuPackets.start().loadSave("CloseConnection").build(), jpegColourPacket(jpeg, 3)));
        for (int i = 0; i < 3; i++) {
            session.readNext(in, sink);
        }

        assertThat(sink.on("camera")).hasSize(1);
        assertThat(sink.malformed).isEmpty();
    }

    @Test
    void splitReadsDecodeTheSame() throws IOException {
        byte[] jpeg = jpeg(104, 80, BufferedImage.TYPE_INT_RGB);
        session.readNext(new OneByteAtATime(jpegColourPacket(jpeg, 9)), sink);

        assertThat(((ImageFrame) sink.on("camera").get(0)).data()).isEqualTo(jpeg);
    }

    @Test
    void garbageAndBrokenPacketsAreReportedAndTheNextImageIsFound() throws IOException {
        byte[] jpeg = jpeg(104, 80, BufferedImage.TYPE_INT_RGB);
        byte[] unknownFormat = TekkotsuPackets.cameraHeader(1, 1, 8, 8, 1).section(8, 8, 3, 0, "RLEImage")
                .u32(0).build();
        byte[] hugeWidth = TekkotsuPackets.cameraHeader(0, 1, 100_000, 80, 2).build();
        byte[] garbage = TekkotsuPackets.start().u32(3).ascii("abc").u8(0).u32(99).build();
        InputStream in = new ByteArrayInputStream(WorldStateSessionTest.concat(unknownFormat, jpegColourPacket(jpeg, 2),
                hugeWidth, jpegColourPacket(jpeg, 3), garbage, jpegColourPacket(jpeg, 4)));
        for (int i = 0; i < 6; i++) {
            session.readNext(in, sink);
        }

        assertThat(sink.malformed).hasSize(3);
        assertThat(sink.malformed.get(0)).contains("'RLEImage'");
        assertThat(sink.malformed.get(1)).contains("camera width is 100000");
        assertThat(sink.malformed.get(2)).contains("starts with 'abc'");
        assertThat(sink.on("camera")).hasSize(3);
    }

    @Test
    void yuvSectionsOutOfOrderAreReported() throws IOException {
        byte[] packet = TekkotsuPackets.cameraHeader(0, 0, 1, 1, 5)
                .section(1, 1, 3, 0, "RawImage").bytes(new byte[1])
                .section(1, 1, 3, 2, "RawImage").bytes(new byte[1])
                .section(1, 1, 3, 1, "RawImage").bytes(new byte[1]).build();
        session.readNext(new ByteArrayInputStream(packet), sink);

        assertThat(sink.malformed).hasSize(1).first().asString().contains("expected Y, U, V");
        assertThat(sink.readings).isEmpty();
    }

    @Test
    void aPacketCutShortEndsTheLink() throws IOException {
        byte[] packet = jpegColourPacket(jpeg(104, 80, BufferedImage.TYPE_INT_RGB), 1);

        assertThatThrownBy(() -> session.readNext(new ByteArrayInputStream(Arrays.copyOf(packet, 200)), sink))
                .isInstanceOf(EOFException.class).hasMessageContaining("JPEG data");
    }
}
