package org.habla.methods.gaze;

import java.time.Duration;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.geometry.CameraModel;
import org.habla.methods.vision.BlobList;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The head control method, type {@code head-control}: it keeps a head-mounted camera on the target.
 * Each {@code blobs} record (from image segmentation) with a blob of the {@code label} turns the head
 * towards it: the blob's angular offset from the image centre (from the camera's field of view, input
 * {@code camera} or params) times {@code gain} is added to the head's pan and tilt, and output
 * {@code head} sends the vector {@code [tiltRad, panRad, nodRad]} within the joint limits. The offset
 * is taken from the head's measured pose (input {@code head}) when wired — the pose read when the image
 * was taken, matched by the readings' times — else from the last command. When the target has been out of sight for {@code lostAfterMs}
 * the head scans: the tilt goes to {@code scanTiltRad} and the pan sweeps between
 * ±{@code scanPanRad} at {@code scanSpeedRadps}, one step every {@code periodMs}, until the target
 * shows again.
 */
public final class HeadControl extends ProcessingMethod {

    private static final InputPort<RecordValue> BLOBS = InputPort.of("blobs", RecordValue.class, Delivery.latest());
    private static final InputPort<RecordValue> CAMERA = InputPort.optional("camera", RecordValue.class,
            Delivery.latest());
    /** The head's measured pose (the output of the same name is the command). */
    private static final InputPort<RecordValue> MEASURED_HEAD = InputPort.optional("head", RecordValue.class,
            Delivery.latest());
    private static final OutputPort<VectorValue> HEAD = OutputPort.of("head", VectorValue.class,
            Shape.vector("rad", "[tiltRad, panRad, nodRad] that keeps the target in view"));
    static final Ports PORTS = Ports.of(BLOBS, CAMERA, MEASURED_HEAD, HEAD);

    private final HeadControlParams params;
    private final HeadLimits limits;
    private final Output<VectorValue> head = output(HEAD);

    private CameraModel camera;
    private final PoseHistory measured = new PoseHistory();
    private HeadPose commanded;
    private long lastSeenMicros = Long.MIN_VALUE;
    private double scanDirection = 1;
    private boolean scanning;
    private boolean warnedNoCamera;

    HeadControl(HeadControlParams params) {
        this.params = params;
        this.limits = params.limits();
        this.commanded = limits.clamp(new HeadPose(params.scanTiltRad(), 0, params.nodRad()));
        input(BLOBS, this::onBlobs);
        input(CAMERA, this::onCamera);
        input(MEASURED_HEAD, this::onHead);
        tickEvery(Duration.ofMillis(params.periodMs()));
    }

    @Override
    protected void onStart() {
        lastSeenMicros = nowMicros();
        if (params.hfovRad() != null && params.vfovRad() != null) {
            camera = new CameraModel(params.hfovRad(), params.vfovRad(), 1, 1, 0);
        }
    }

    private void onCamera(RecordValue record, Sample sample) {
        CameraModel.fromRecord(record).ifPresent(c -> camera = new CameraModel(
                params.hfovRad() != null ? params.hfovRad() : c.hfovRad(),
                params.vfovRad() != null ? params.vfovRad() : c.vfovRad(), c.width(), c.height(), c.heightM()));
    }

    private void onHead(RecordValue record, Sample sample) {
        HeadPose.fromRecord(record).ifPresent(p -> measured.add(sample.sourceMicros(), p));
    }

    private void onBlobs(RecordValue record, Sample sample) {
        BlobList list = BlobList.fromRecord(record).orElse(null);
        BlobList.Entry blob = list == null ? null : list.largest(params.label(), BlobList.Entry::centred).orElse(null);
        if (blob == null) {
            return;
        }
        if (camera == null || list.width() <= 0 || list.height() <= 0) {
            if (!warnedNoCamera) {
                warnedNoCamera = true;
                log().warn("{}: cannot aim without the image size and field of view; wire input camera or set "
                        + "hfovRad and vfovRad", id());
            }
            return;
        }
        CameraModel cam = camera.withSize(list.width(), list.height());
        double[] ray = cam.ray(blob.cx(), blob.cy());
        double left = Math.atan(ray[1]);
        double up = Math.atan(ray[2]);
        HeadPose then = measured.at(sample.sourceMicros());
        HeadPose base = then != null ? then : commanded;
        double pan = base.panRad() + (Math.abs(left) > params.deadbandRad() ? params.gain() * left : 0);
        double tilt = base.tiltRad() + (Math.abs(up) > params.deadbandRad() ? params.gain() * up : 0);
        lastSeenMicros = nowMicros();
        scanning = false;
        command(new HeadPose(tilt, pan, params.nodRad()));
    }

    @Override
    protected void onTick(long nowMicros) {
        if (nowMicros - lastSeenMicros < params.lostAfterMs() * 1000L) {
            return;
        }
        if (!scanning) {
            scanning = true;
            scanDirection = commanded.panRad() >= 0 ? 1 : -1;
        }
        double step = params.scanSpeedRadps() * params.periodMs() / 1000.0;
        double pan = commanded.panRad() + scanDirection * step;
        if (Math.abs(pan) >= params.scanPanRad()) {
            pan = Math.copySign(params.scanPanRad(), pan);
            scanDirection = -scanDirection;
        }
        command(new HeadPose(params.scanTiltRad(), pan, params.nodRad()));
    }

    private void command(HeadPose wanted) {
        commanded = limits.clamp(wanted);
        emit(head, commanded.toVector());
    }


    /** Whether the head is scanning for a lost target. */
    public boolean scanning() {
        return scanning;
    }

    /** Makes {@code head-control} methods. */
    public static final class Provider extends SimpleMethodProvider<HeadControlParams> {
        public Provider() {
            super("head-control", "Turns the head to keep the target's blob in the middle of the image; scans when it is lost",
                    HeadControlParams.class, PORTS, (layer, p) -> new HeadControl(p), Layer.PROCESSING);
        }
    }
}
