package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.io.InputStream;
import java.util.List;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.driver.SessionChannel;
import org.habla.sample.ImageFrame;

/**
 * The session on the raw camera server over TCP (port 10011): every image packet becomes a
 * {@code camera} frame — JPEG sections as they are ({@code "jpeg"}, size from the header),
 * uncompressed single channels as {@code "gray8"}, uncompressed Y, U, V sections as {@code "bgr8"}
 * (chroma upsampled, JFIF YCbCr→RGB, the same colours a JPEG decoder gives).
 *
 * <p>The server's {@code "CloseConnection"} and sensor ({@code #POS}) strings are skipped. A packet
 * that breaks the layout is reported once and the stream is searched for the next
 * {@code "TekkotsuImage"}; a stream where none turns up within {@link #RESYNC_LIMIT_BYTES} ends the
 * link.
 */
final class RawCamSession implements LinkSession {

    private final SessionChannel cameraChannel = new SessionChannel(TekkotsuChannels.CAMERA);

    static final int RESYNC_LIMIT_BYTES = 1 << 20;
    /** Sensor strings are under 1000 bytes; anything longer here is not a packet type. */
    private static final int MAX_TYPE_CHARS = 4_096;

    private boolean outOfStep;

    @Override
    public void readNext(InputStream in, ReadingSink sink) throws IOException {
        WireInput wire = new WireInput(in);
        try {
            if (outOfStep) {
                wire.skipPast(CameraPacket.MAGIC, RESYNC_LIMIT_BYTES, "camera packet");
            } else {
                String type = wire.loadSaveString(MAX_TYPE_CHARS, "camera packet type");
                if (type.equals("CloseConnection") || type.startsWith("#POS")) {
                    return;
                }
                if (!type.equals(CameraPacket.MAGIC_TEXT)) {
                    throw new WireInput.MalformedFieldException("camera packet starts with '"
                            + WireInput.abbreviate(type) + "', not '" + CameraPacket.MAGIC_TEXT + "'");
                }
            }
            CameraPacket packet = CameraPacket.readAfterMagic(wire);
            outOfStep = false;
            frame(packet, sink);
        } catch (WireInput.MalformedFieldException e) {
            outOfStep = true;
            sink.malformed(e.getMessage() + "; skipping to the next camera packet");
        }
    }

    private void frame(CameraPacket p, ReadingSink sink) {
        List<CameraPacket.Section> s = p.sections();
        CameraPacket.Section first = s.get(0);
        if (first.format().startsWith("JPEG")) {
            cameraChannel.publish(sink, ImageFrame.wrap(p.width(), p.height(), "jpeg", first.data()));
        } else if (s.size() == 1) {
            cameraChannel.publish(sink, ImageFrame.wrap(first.width(), first.height(), "gray8",
                    first.data()));
        } else {
            String problem = yuvProblem(s);
            if (problem != null) {
                sink.malformed("colour camera packet " + p.frame() + " skipped: " + problem);
                return;
            }
            cameraChannel.publish(sink, ImageFrame.wrap(first.width(), first.height(), "bgr8",
                    YuvToBgr.convert(s.get(0), s.get(1), s.get(2))));
        }
    }

    private static String yuvProblem(List<CameraPacket.Section> s) {
        for (int i = 0; i < 3; i++) {
            CameraPacket.Section c = s.get(i);
            if (!c.format().equals("RawImage")) {
                return "section " + i + " is " + c.format() + " among raw sections";
            }
            if (c.channel() != i) {
                return "section " + i + " is channel " + c.channel() + ", expected Y, U, V (0, 1, 2) in order";
            }
        }
        return null;
    }
}
