package org.habla.drivers.pioneer;

import java.util.ArrayList;
import java.util.List;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code bumpers} reading of a Pioneer, from one SIP: each bumper segment the robot has, front and rear, and
 * whether any of either is pressed.
 *
 * @param front the front segments, first one first: true while pressed
 * @param rear  the rear segments, first one first: true while pressed
 */
record BumperReading(List<Boolean> front, List<Boolean> rear) implements RecordForm {

    static final RecordLayout<BumperReading> LAYOUT = RecordLayout.of(BumperReading.class)
            .flags("front", b -> flags(b.front)).doc("each front segment, first one first: true while pressed")
            .flags("rear", b -> flags(b.rear)).doc("each rear segment, first one first: true while pressed")
            .flag("frontHit", b -> b.front.contains(true)).doc("some front segment is pressed")
            .flag("rearHit", b -> b.rear.contains(true)).doc("some rear segment is pressed")
            .build();

    BumperReading {
        front = List.copyOf(front);
        rear = List.copyOf(rear);
    }

    /** The first {@code frontCount} front and {@code rearCount} rear segments {@code sip} reports. */
    static BumperReading of(StandardSip sip, int frontCount, int rearCount) {
        List<Boolean> front = new ArrayList<>(frontCount);
        List<Boolean> rear = new ArrayList<>(rearCount);
        for (int i = 0; i < frontCount; i++) {
            front.add(sip.frontBumper(i));
        }
        for (int i = 0; i < rearCount; i++) {
            rear.add(sip.rearBumper(i));
        }
        return new BumperReading(front, rear);
    }

    @Override
    public RecordLayout<BumperReading> layout() {
        return LAYOUT;
    }

    private static boolean[] flags(List<Boolean> segments) {
        boolean[] a = new boolean[segments.size()];
        for (int i = 0; i < a.length; i++) {
            a[i] = segments.get(i);
        }
        return a;
    }
}
