package org.habla.sim.aibo;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Collections;
import org.junit.jupiter.api.Test;

/** The camera's #POS sensor string, byte for byte as Tekkotsu's PostureEngine writes it in condensed form. */
class PostureStringTest {

    private static String zeros(int n) {
        return String.join(" ", Collections.nCopies(n, "0"));
    }

    @Test
    void aPostureIsWrittenItemByItemWithEveryNumberAsCsPercentG() {
        float[] outputs = new float[Ers7Layout.NUM_OUTPUTS];
        outputs[Ers7Layout.HEAD_TILT] = 0.5235988f;
        float[] buttons = new float[Ers7Layout.NUM_BUTTONS];
        buttons[9] = 0.8f;
        float[] sensors = {1500f, 310f, 139f, 0f, 0f, -9.81f, 0.95f, 30f, 2000f, 8.36f, -600f};
        float[] duties = new float[Ers7Layout.NUM_PID_JOINTS];
        duties[1] = 0.0001234f;

        String text = RawCamServer.posture(new Ers7Layout.Snapshot(outputs, sensors, buttons, duties), 3_200);

        assertThat(text).isEqualTo("#POS\n"
                + "condensed ERS-7\n"
                + "meta-info = 3200 400\n"
                + "outputs = " + zeros(12) + " 0.523599 " + zeros(Ers7Layout.NUM_OUTPUTS - 13) + "\n"
                + "buttons = " + zeros(9) + " 0.8\n"
                + "sensors = 1500 310 139 0 0 -9.81 0.95 30 2000 8.36 -600\n"
                + "pidduties = 0 0.0001234 " + zeros(Ers7Layout.NUM_PID_JOINTS - 2) + "\n"
                + "#END\n");
    }

    @Test
    void aWalkingPostureWithEveryButtonPressedStaysUnderTheThousandBytesTekkotsu5sClientAccepts() {
        float[] buttons = new float[Ers7Layout.NUM_BUTTONS];
        java.util.Arrays.fill(buttons, 0.8123f);
        Ers7Layout.Snapshot walking = Ers7Layout.snapshot(new double[] {-1.2345678, 1.5432109, 0.7654321}, 0.7,
                new float[] {1499.876f, 310.4567f, 139.1234f}, buttons, 12_345.678);

        String text = RawCamServer.posture(walking, 123_456_789L);

        assertThat(text.length() + 5).as("the LoadSave string: length, text, NUL").isLessThan(1_000);
    }
}
