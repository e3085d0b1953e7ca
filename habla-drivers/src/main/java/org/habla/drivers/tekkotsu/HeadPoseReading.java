package org.habla.drivers.tekkotsu;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/** The {@code head-pose} reading of an ERS-7: where its three head joints are, from one World State packet. */
record HeadPoseReading(double tiltRad, double panRad, double nodRad) implements RecordForm {

    static final RecordLayout<HeadPoseReading> LAYOUT = RecordLayout.of(HeadPoseReading.class)
            .number("tiltRad", HeadPoseReading::tiltRad).unit("rad").frame("from the body; negative looks down")
            .doc("the neck's tilt")
            .number("panRad", HeadPoseReading::panRad).unit("rad").frame("from the body; positive turns to the left")
            .doc("the pan")
            .number("nodRad", HeadPoseReading::nodRad).unit("rad").frame("from the neck; positive looks up")
            .doc("the head's nod")
            .build();

    @Override
    public RecordLayout<HeadPoseReading> layout() {
        return LAYOUT;
    }
}
