package org.habla.methods.sensors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.geometry.CameraModel;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The general camera method, type {@code camera}: it stores the frames of a camera channel (input
 * {@code image}) and hands them on (output {@code image}), at most {@code maxFps} a second when set.
 * Frames whose bytes do not start as their encoding says ({@code jpeg}, {@code png}) are dropped and
 * counted, so a damaged frame never reaches image processing. Output {@code camera} describes the camera
 * for the methods that measure in its images: the record {@code {"hfovRad","vfovRad","width","height","heightM"}}
 * from the channel's metadata (or params), with the size of the frames that really arrive; it is sent
 * with the first frame and again whenever the frame size changes.
 */
public final class Camera extends SensorActuatorMethod {

    private static final OutputPort<ImageFrame> IMAGE_OUT = OutputPort.of("image", ImageFrame.class,
            Shape.of(org.habla.sample.PayloadKind.IMAGE));
    private static final OutputPort<RecordValue> CAMERA = OutputPort.of("camera", RecordValue.class,
            Shape.record("the camera's geometry and the size of its frames", CameraModel.LAYOUT));
    private static final InputPort<ImageFrame> IMAGE_IN = InputPort.of("image", ImageFrame.class, Delivery.latest());
    static final Ports PORTS = Ports.of(IMAGE_OUT, CAMERA, IMAGE_IN);

    private final CameraParams params;
    private final Output<ImageFrame> imageOut = output(IMAGE_OUT);
    private final Output<RecordValue> cameraOut = output(CAMERA);
    private final Input<ImageFrame> image = input(IMAGE_IN, this::onImage);

    private JsonNode metadata = JsonNodeFactory.instance.objectNode();
    private int width;
    private int height;
    private boolean warnedSize;
    private boolean warnedGeometry;
    private long nextDueMicros = Long.MIN_VALUE;
    private long malformed;
    private long skipped;

    Camera(CameraParams params) {
        this.params = params;
    }

    @Override
    protected void onStart() {
        metadata = channelOf(image).map(ChannelDescriptor::metadata).map(m -> (JsonNode) m)
                .orElse(JsonNodeFactory.instance.objectNode());
    }

    private void onImage(ImageFrame frame, Sample sample) {
        if (!wellFormed(frame)) {
            malformed++;
            if (malformed == 1 || malformed % 1000 == 0) {
                log().warn("{}: a {} frame of {} bytes does not start as {} does; dropped ({} so far)", id(),
                        frame.encoding(), frame.byteCount(), frame.encoding(), malformed);
            }
            return;
        }
        if (params.maxFps() > 0) {
            long interval = Math.round(1_000_000 / params.maxFps());
            long t = sample.sourceMicros();
            if (nextDueMicros != Long.MIN_VALUE && t < nextDueMicros - interval / 10) {
                skipped++;
                return;
            }
            nextDueMicros = (nextDueMicros == Long.MIN_VALUE || t > nextDueMicros + interval) ? t + interval
                    : nextDueMicros + interval;
        }
        if (frame.width() != width || frame.height() != height) {
            width = frame.width();
            height = frame.height();
            checkSize();
            describe();
        }
        emit(imageOut, frame);
    }

    private void checkSize() {
        JsonNode w = metadata.path("width");
        JsonNode h = metadata.path("height");
        if (w.isInt() && h.isInt() && (w.intValue() != width || h.intValue() != height) && !warnedSize) {
            warnedSize = true;
            log().warn("{}: frames are {}x{} but the channel says {}x{}; the frames' own size is used", id(),
                    width, height, w.intValue(), h.intValue());
        }
    }

    private void describe() {
        ObjectNode given = JsonNodeFactory.instance.objectNode();
        given.setAll((ObjectNode) metadata.deepCopy());
        if (params.hfovRad() != null) {
            given.put("hfovRad", params.hfovRad());
        }
        if (params.vfovRad() != null) {
            given.put("vfovRad", params.vfovRad());
        }
        if (params.heightM() != null) {
            given.put("heightM", params.heightM());
        }
        given.put("width", width).put("height", height);
        if (!given.path("heightM").isNumber()) {
            given.put("heightM", 0.0);
        }
        CameraModel model = CameraModel.fromJson(given, null).orElse(null);
        if (model == null) {
            if (!warnedGeometry) {
                warnedGeometry = true;
                log().warn("{}: the camera's field of view is unknown (no hfovRad/vfovRad in the channel metadata or "
                        + "params); output camera stays silent", id());
            }
            return;
        }
        emit(cameraOut, model.toRecord());
    }

    private static boolean wellFormed(ImageFrame frame) {
        byte[] head = firstBytes(frame, 8);
        return switch (frame.encoding()) {
            case "jpeg" -> head.length >= 3 && (head[0] & 0xff) == 0xFF && (head[1] & 0xff) == 0xD8 && (head[2] & 0xff) == 0xFF;
            case "png" -> head.length >= 8 && (head[0] & 0xff) == 0x89 && head[1] == 'P' && head[2] == 'N' && head[3] == 'G';
            default -> true;
        };
    }

    /** The first {@code n} bytes of the frame, read without copying the whole image. */
    private static byte[] firstBytes(ImageFrame frame, int n) {
        byte[][] got = {new byte[0]};
        try {
            frame.writeTo(new java.io.OutputStream() {
                @Override
                public void write(int b) {
                    if (got[0].length < n) {
                        got[0] = java.util.Arrays.copyOf(got[0], got[0].length + 1);
                        got[0][got[0].length - 1] = (byte) b;
                    }
                }

                @Override
                public void write(byte[] b, int off, int len) {
                    int take = Math.min(len, n - got[0].length);
                    if (take > 0) {
                        byte[] more = java.util.Arrays.copyOf(got[0], got[0].length + take);
                        System.arraycopy(b, off, more, got[0].length, take);
                        got[0] = more;
                    }
                }
            });
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return got[0];
    }

    /** Frames dropped because their bytes did not match their encoding, since start. */
    public long malformed() {
        return malformed;
    }

    /** Frames left out to keep within {@code maxFps}, since start. */
    public long skipped() {
        return skipped;
    }

    /** Makes {@code camera} methods. */
    public static final class Provider extends SimpleMethodProvider<CameraParams> {
        public Provider() {
            super("camera", "Hands on a camera's frames (checked, optionally rate-capped) and describes its geometry",
                    CameraParams.class, PORTS, (layer, p) -> new Camera(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
