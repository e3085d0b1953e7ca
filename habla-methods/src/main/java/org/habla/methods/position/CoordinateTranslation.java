package org.habla.methods.position;

import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.gaze.HeadPose;
import org.habla.methods.gaze.PoseHistory;
import org.habla.methods.geometry.CameraModel;
import org.habla.methods.geometry.PlanarPose;
import org.habla.methods.perception.NearestObstacle;
import org.habla.methods.vision.BlobList;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The coordinate translation method, type {@code coordinate-translation}: it turns what a sensor saw
 * into the {@code position} of the target in the robot frame, {@code {"xM","yM","distanceM","angleRad","seen"}}
 * (x forward, y left, angle positive to the left; for a blob, distance from the edge of the robot's
 * body, {@code bodyRadiusM} around its origin, to the target's near surface). What it works from depends on which inputs the config wires:
 *
 * <ul>
 *   <li>{@code nearest}: a {@code nearest} record of a range sensor, already in the robot frame: it is
 *       handed on with {@code seen} added.</li>
 *   <li>{@code blobs} (with {@code head} and {@code camera}): the image segmentation's blobs; the
 *       largest blob of the {@code label} is located by {@link BlobFix} from its size (a ball of
 *       {@code targetRadiusM}) or from where its ray meets the floor, through the head's pan, tilt and
 *       nod (as they were when the image was taken, matched by the readings' times) and the camera's
 *       geometry. With no such blob the record says {@code seen: false} and keeps
 *       the last sighting.</li>
 *   <li>{@code odometry} (optional, a pose record {@code xM, yM, thetaRad}): adds the world-frame
 *       {@code xWorldM}, {@code yWorldM} of the target.</li>
 * </ul>
 */
public final class CoordinateTranslation extends ProcessingMethod {

    private static final InputPort<RecordValue> NEAREST = InputPort.optional("nearest", RecordValue.class,
            Delivery.latest());
    private static final InputPort<RecordValue> BLOBS = InputPort.optional("blobs", RecordValue.class,
            Delivery.latest());
    private static final InputPort<RecordValue> HEAD = InputPort.optional("head", RecordValue.class,
            Delivery.latest());
    private static final InputPort<RecordValue> CAMERA = InputPort.optional("camera", RecordValue.class,
            Delivery.latest());
    private static final InputPort<RecordValue> ODOMETRY = InputPort.optional("odometry", RecordValue.class,
            Delivery.latest());
    private static final OutputPort<RecordValue> POSITION = OutputPort.of("position", RecordValue.class,
            Shape.record("the target in the robot frame (distance to its near surface); seen false keeps the last sighting",
                    TargetPosition.LAYOUT));
    static final Ports PORTS = Ports.of(NEAREST, BLOBS, HEAD, CAMERA, ODOMETRY, POSITION);

    private final CoordinateTranslationParams params;
    private final Output<RecordValue> position = output(POSITION);

    private CameraModel camera;
    private final PoseHistory heads = new PoseHistory();
    private PlanarPose odometry;
    private double lastX;
    private double lastY;
    private double lastDistance;
    private boolean everSeen;
    private long rejected;
    private boolean warnedNoCamera;

    CoordinateTranslation(CoordinateTranslationParams params) {
        this.params = params;
        input(NEAREST, this::onNearest);
        input(BLOBS, this::onBlobs);
        input(HEAD, this::onHead);
        input(CAMERA, this::onCamera);
        input(ODOMETRY, this::onOdometry);
        if (params.hfovRad() != null && params.vfovRad() != null && params.cameraHeightM() != null) {
            camera = new CameraModel(params.hfovRad(), params.vfovRad(), 1, 1, params.cameraHeightM());
        }
    }

    private void onCamera(RecordValue record, Sample sample) {
        CameraModel fromRecord = CameraModel.fromRecord(record).orElse(null);
        if (fromRecord == null) {
            rejected++;
            if (rejected == 1 || rejected % 1000 == 0) {
                log().warn("{}: camera record {} is not a camera; ignored ({} rejected so far)", id(), record, rejected);
            }
            return;
        }
        camera = new CameraModel(
                params.hfovRad() != null ? params.hfovRad() : fromRecord.hfovRad(),
                params.vfovRad() != null ? params.vfovRad() : fromRecord.vfovRad(),
                fromRecord.width(), fromRecord.height(),
                params.cameraHeightM() != null ? params.cameraHeightM() : fromRecord.heightM());
    }

    private void onHead(RecordValue record, Sample sample) {
        HeadPose.fromRecord(record).ifPresentOrElse(p -> heads.add(sample.sourceMicros(), p), () -> rejected++);
    }

    private void onOdometry(RecordValue record, Sample sample) {
        PlanarPose.fromRecord(record).ifPresentOrElse(p -> odometry = p, () -> rejected++);
    }

    private void onNearest(RecordValue record, Sample sample) {
        NearestObstacle nearest = NearestObstacle.fromRecord(record);
        double x = nearest.xM();
        double y = nearest.yM();
        boolean numbers = Double.isFinite(x) && Double.isFinite(y);
        if (numbers) {
            remember(x, y, Double.isNaN(nearest.distanceM()) ? Math.hypot(x, y) : nearest.distanceM());
        } else {
            rejected++;
        }
        emitPosition(numbers, null);
    }

    private void onBlobs(RecordValue record, Sample sample) {
        Optional<BlobList> list = BlobList.fromRecord(record);
        if (list.isEmpty() && record.has("blobs")) {
            rejected++;
        }
        BlobList.Entry blob = list.flatMap(l -> l.largest(params.label(), BlobList.Entry::boxed)).orElse(null);
        if (blob == null) {
            emitPosition(false, null);
            return;
        }
        CameraModel cam = cameraFor(list.get());
        if (cam == null) {
            if (!warnedNoCamera) {
                warnedNoCamera = true;
                log().warn("{}: a blob was seen but the camera geometry is unknown; wire input camera or set "
                        + "hfovRad, vfovRad and cameraHeightM", id());
            }
            emitPosition(false, null);
            return;
        }
        BlobFix fix = new BlobFix(cam, params.targetRadiusM(), params.cameraXM(), params.lensForwardM(),
                params.minRadiusPx());
        BlobFix.Fix found = fix.locate(blob.cx(), blob.cy(), blob.x(), blob.y(), blob.w(), blob.h(),
                headAt(sample.sourceMicros())).orElse(null);
        if (found == null) {
            emitPosition(false, null);
            return;
        }
        remember(found.xM(), found.yM(),
                Math.max(0, Math.hypot(found.xM(), found.yM()) - params.targetRadiusM() - params.bodyRadiusM()));
        emitPosition(true, found);
    }

    /** Where the head pointed when the image was taken (its reading time), straight ahead if unknown. */
    private HeadPose headAt(long imageMicros) {
        HeadPose p = heads.at(imageMicros);
        return p == null ? HeadPose.STRAIGHT : p;
    }

    /** The camera with this image's size, from the blobs record's width and height. */
    private CameraModel cameraFor(BlobList blobs) {
        if (camera == null) {
            return null;
        }
        if (blobs.width() > 0 && blobs.height() > 0) {
            return camera.withSize(blobs.width(), blobs.height());
        }
        return camera.width() > 1 ? camera : null;
    }

    private void remember(double x, double y, double distance) {
        lastX = x;
        lastY = y;
        lastDistance = distance;
        everSeen = true;
    }

    private void emitPosition(boolean seen, BlobFix.Fix fix) {
        Double xWorld = null;
        Double yWorld = null;
        if (odometry != null && everSeen) {
            double c = Math.cos(odometry.thetaRad());
            double s = Math.sin(odometry.thetaRad());
            xWorld = odometry.xM() + c * lastX - s * lastY;
            yWorld = odometry.yM() + s * lastX + c * lastY;
        }
        emit(position, RecordValue.of(new TargetPosition(lastX, lastY, lastDistance,
                everSeen ? Math.atan2(lastY, lastX) : 0.0, seen, fix == null ? null : fix.method(),
                fix == null ? null : fix.groundRangeM(), xWorld, yWorld)));
    }

    /** Inputs that were not what their record should be, since start. */
    public long rejected() {
        return rejected;
    }

    /** Makes {@code coordinate-translation} methods. */
    public static final class Provider extends SimpleMethodProvider<CoordinateTranslationParams> {
        public Provider() {
            super("coordinate-translation",
                    "Places the target in the robot frame (and the world frame) from a range reading or a camera blob",
                    CoordinateTranslationParams.class, PORTS, (layer, p) -> new CoordinateTranslation(p), Layer.PROCESSING);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
