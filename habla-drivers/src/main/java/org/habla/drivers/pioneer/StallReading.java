package org.habla.drivers.pioneer;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code stall} reading of a Pioneer, from one SIP: which drive wheels are stalled.
 *
 * @param left  whether the left wheel is stalled
 * @param right whether the right wheel is stalled
 */
record StallReading(boolean left, boolean right) implements RecordForm {

    static final RecordLayout<StallReading> LAYOUT = RecordLayout.of(StallReading.class)
            .flag("left", StallReading::left).doc("the left wheel is stalled")
            .flag("right", StallReading::right).doc("the right wheel is stalled")
            .build();

    static StallReading of(StandardSip sip) {
        return new StallReading(sip.leftStalled(), sip.rightStalled());
    }

    @Override
    public RecordLayout<StallReading> layout() {
        return LAYOUT;
    }
}
