package org.habla.methods.gaze;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;

/**
 * The angles of a three-joint head: the neck's tilt (negative looks down), the pan (positive turns to
 * the left) and the head's nod (positive looks up). It travels as the {@code head-pose} record
 * {@code {"tiltRad","panRad","nodRad"}} and, as a command, as the vector {@code [tiltRad, panRad, nodRad]}.
 */
public record HeadPose(double tiltRad, double panRad, double nodRad) implements RecordForm {

    /** The fields of a head-pose record. */
    public static final RecordLayout<HeadPose> LAYOUT = RecordLayout.of(HeadPose.class)
            .number("tiltRad", HeadPose::tiltRad).unit("rad").frame("from the body; negative looks down")
            .doc("the neck's tilt")
            .number("panRad", HeadPose::panRad).unit("rad").frame("from the body; positive turns to the left")
            .doc("the pan")
            .number("nodRad", HeadPose::nodRad).unit("rad").frame("from the neck; positive looks up")
            .doc("the head's nod")
            .build();

    public static final HeadPose STRAIGHT = new HeadPose(0, 0, 0);

    public HeadPose {
        if (!Double.isFinite(tiltRad) || !Double.isFinite(panRad) || !Double.isFinite(nodRad)) {
            throw new IllegalArgumentException("head angles must be finite, were " + tiltRad + ", " + panRad + ", " + nodRad);
        }
    }

    /** How far the camera looks up (negative: down): tilt and nod together, as if both turned about one axis. */
    public double pitchRad() {
        return tiltRad + nodRad;
    }

    public RecordValue toRecord() {
        return RecordValue.of(this);
    }

    @Override
    public RecordLayout<HeadPose> layout() {
        return LAYOUT;
    }

    public VectorValue toVector() {
        return VectorValue.of(tiltRad, panRad, nodRad);
    }

    /** Reads the record; a missing nod counts as 0. Empty when tilt or pan is missing or not finite. */
    public static Optional<HeadPose> fromRecord(RecordValue record) {
        Optional<HeadPose> typed = record.form(HeadPose.class);
        return typed.isPresent() ? typed : read(record);
    }

    private static Optional<HeadPose> read(RecordValue record) {
        JsonNode t = record.get("tiltRad");
        JsonNode p = record.get("panRad");
        JsonNode n = record.get("nodRad");
        if (!t.isNumber() || !p.isNumber() || !(n.isMissingNode() || n.isNumber())) {
            return Optional.empty();
        }
        double nod = n.isNumber() ? n.doubleValue() : 0;
        if (!Double.isFinite(t.doubleValue()) || !Double.isFinite(p.doubleValue()) || !Double.isFinite(nod)) {
            return Optional.empty();
        }
        return Optional.of(new HeadPose(t.doubleValue(), p.doubleValue(), nod));
    }

    /** Reads the command vector {@code [tilt, pan, nod]} (nod may be left out). Empty when it is not one. */
    public static Optional<HeadPose> fromVector(VectorValue v) {
        if (v.size() < 2 || v.size() > 3) {
            return Optional.empty();
        }
        double nod = v.size() == 3 ? v.get(2) : 0;
        if (!Double.isFinite(v.get(0)) || !Double.isFinite(v.get(1)) || !Double.isFinite(nod)) {
            return Optional.empty();
        }
        return Optional.of(new HeadPose(v.get(0), v.get(1), nod));
    }
}
