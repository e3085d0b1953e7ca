package org.habla.sim.aibo;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.function.LongFunction;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Raw Cam Server over TCP (port 10011): the pinhole camera's picture at the resolution of
 * {@code vision.rawcam.y_skip}, every 33 ms of simulated time (or {@code vision.rawcam.interval}), as
 * one {@code JPEGColor} section (quality 85, 2× subsampled chroma, as Tekkotsu sends by default):
 * <pre>
 * "TekkotsuImage" | i32 encoding 0 | i32 compression 1 | u32 width | u32 height | u32 time ms | u32 frame
 * "FbkImage" | u32 width | u32 height | u32 layer (5 - skip) | u32 channel 0 | "JPEGColor" | u32 n | n bytes
 * </pre>
 * Strings are LoadSave strings (u32 length, the characters, a NUL). Lines the client sends are the
 * camera's upstream commands: {@code refreshSensors} answers one {@code #POS} sensor string,
 * {@code startSensors}/{@code stopSensors} add one to every frame or stop it.
 */
final class RawCamServer implements TekkotsuSocket.Client {

    private static final Logger LOG = LoggerFactory.getLogger(RawCamServer.class);

    /** The ERS-7 camera delivers a frame every 33.4 ms. */
    static final long FRAME_PERIOD_MS = 33;
    /** However fast the clock runs, frames are rendered at most this often in real time. */
    static final long MIN_REAL_PERIOD_MS = 20;
    static final int[] WIDTH_BY_SKIP = {416, 208, 104, 52, 26, 13};
    static final int[] HEIGHT_BY_SKIP = {320, 160, 80, 40, 20, 10};
    private static final int MAX_LINE_BYTES = 256;

    private final LongFunction<CameraView> views;
    private final Ers7Body body;
    private final AiboTime clock;
    private final RobotSettings settings;

    RawCamServer(LongFunction<CameraView> views, Ers7Body body, AiboTime clock, RobotSettings settings) {
        this.views = views;
        this.body = body;
        this.clock = clock;
        this.settings = settings;
    }

    @Override
    public void serve(Socket socket) throws IOException, InterruptedException {
        OutputStream out = socket.getOutputStream();
        Upstream upstream = new Upstream();
        Thread reader = Thread.ofVirtual().start(() -> upstream.read(socket, out));
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        try {
            long frame = clock.nowMs() / FRAME_PERIOD_MS + 1;
            while (!socket.isClosed()) {
                long at = frame * FRAME_PERIOD_MS;
                clock.sleepUntil(at);
                long realStart = System.nanoTime();
                int skip = settings.rawCamSkip();
                PinholeCamera camera = new PinholeCamera(WIDTH_BY_SKIP[skip], HEIGHT_BY_SKIP[skip]);
                byte[] packet = packet(jpeg(writer, camera.render(views.apply(at))), camera, skip, at, frame);
                synchronized (out) {
                    out.write(packet);
                    if (upstream.streamSensors) {
                        out.write(sensorString(at));
                    }
                    out.flush();
                }
                long interval = Math.max(1, (settings.rawCamIntervalMs() + FRAME_PERIOD_MS - 1) / FRAME_PERIOD_MS);
                long spentMs = (System.nanoTime() - realStart) / 1_000_000;
                Thread.sleep(Math.max(0, MIN_REAL_PERIOD_MS - spentMs));
                frame = Math.max(frame + interval, clock.nowMs() / FRAME_PERIOD_MS);
            }
        } finally {
            writer.dispose();
            reader.interrupt();
        }
    }

    /** The client's upstream lines, read on their own thread. */
    private final class Upstream {
        volatile boolean streamSensors;

        void read(Socket socket, OutputStream out) {
            try {
                LineFramer lines = new LineFramer(socket.getInputStream(), MAX_LINE_BYTES);
                while (true) {
                    String line;
                    try {
                        line = lines.readText(StandardCharsets.UTF_8);
                    } catch (FrameException e) {
                        if (e.fatal()) {
                            break;
                        }
                        LOG.info("raw camera: ignored a line: {}", e.getMessage());
                        continue;
                    }
                    if (line == null) {
                        break;
                    }
                    switch (line.strip()) {
                        case "startSensors" -> streamSensors = true;
                        case "stopSensors" -> streamSensors = false;
                        case "refreshSensors" -> {
                            synchronized (out) {
                                out.write(sensorString(clock.nowMs()));
                                out.flush();
                            }
                        }
                        default -> LOG.info("raw camera: ignored the line '{}'", Abbreviation.of(line));
                    }
                }
            } catch (IOException e) {
                // the client left
            }
            try {
                socket.close();
            } catch (IOException e) {
                // closing anyway: the frame loop ends on its next write
            }
        }
    }

    static byte[] jpeg(ImageWriter writer, BufferedImage image) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(8_192);
        try (MemoryCacheImageOutputStream stream = new MemoryCacheImageOutputStream(bytes)) {
            writer.setOutput(stream);
            ImageWriteParam p = writer.getDefaultWriteParam();
            p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            p.setCompressionQuality(0.85f);
            writer.write(null, new IIOImage(image, null, null), p);
        }
        return bytes.toByteArray();
    }

    static byte[] packet(byte[] jpeg, PinholeCamera camera, int skip, long timeMs, long frame) {
        ByteBuffer b = ByteBuffer.allocate(256 + jpeg.length).order(ByteOrder.LITTLE_ENDIAN);
        loadSave(b, "TekkotsuImage");
        b.putInt(0).putInt(1).putInt(camera.width()).putInt(camera.height()).putInt((int) timeMs).putInt((int) frame);
        loadSave(b, "FbkImage");
        b.putInt(camera.width()).putInt(camera.height()).putInt(5 - skip).putInt(0);
        loadSave(b, "JPEGColor");
        b.putInt(jpeg.length).put(jpeg);
        byte[] out = new byte[b.position()];
        b.flip().get(out);
        return out;
    }

    /** The {@code #POS} sensor string in Tekkotsu's condensed posture form, as a LoadSave string. */
    private byte[] sensorString(long timeMs) {
        byte[] chars = posture(body.snapshot(timeMs), timeMs).getBytes(StandardCharsets.US_ASCII);
        ByteBuffer b = ByteBuffer.allocate(chars.length + 5).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(chars.length).put(chars).put((byte) 0);
        return b.array();
    }

    /** The text of a {@code #POS} sensor string: one item a line, every number as C's {@code %g} prints it. */
    static String posture(Ers7Layout.Snapshot s, long timeMs) {
        return "#POS\ncondensed " + Ers7Layout.MODEL + "\nmeta-info = " + timeMs + " "
                + timeMs / WorldStateServer.SENSOR_PERIOD_MS * 4 + "\n"
                + "outputs = " + numbers(s.outputs()) + "\nbuttons = " + numbers(s.buttons()) + "\nsensors = "
                + numbers(s.sensors()) + "\npidduties = " + numbers(s.duties()) + "\n#END\n";
    }

    private static String numbers(float[] values) {
        StringBuilder b = new StringBuilder();
        for (float v : values) {
            if (!b.isEmpty()) {
                b.append(' ');
            }
            b.append(PrintfG.of(v));
        }
        return b.toString();
    }

    private static void loadSave(ByteBuffer b, String text) {
        byte[] chars = text.getBytes(StandardCharsets.US_ASCII);
        b.putInt(chars.length).put(chars).put((byte) 0);
    }
}
