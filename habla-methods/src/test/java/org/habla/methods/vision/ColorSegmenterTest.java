package org.habla.methods.vision;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.habla.sample.ImageFrame;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class ColorSegmenterTest {

    @BeforeAll
    static void loadOpenCv() {
        OpenCvLibrary.load();
    }

    @Test
    void aFrameIsSegmentedAlikeWhateverFramesOfOtherSizesCameBefore() {
        ColorSegmenter segmenter = new ColorSegmenter(ImageSegmentationParams.defaults());
        ImageFrame small = new CameraScene(208, 160, 0.2).render(new Random(1), true, 0.8, 0.1);
        ImageFrame large = new CameraScene(416, 320, 0.2).render(new Random(2), true, 1.5, -0.2);

        Segmentation first = segmenter.segment(small);
        segmenter.segment(large);
        Segmentation again = segmenter.segment(small);

        assertThat(first.readable()).isTrue();
        assertThat(first.blobs()).isNotEmpty();
        assertThat(again).isEqualTo(first);
        assertThat(segmenter.segment(large).width()).isEqualTo(416);
    }
}
