package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import edu.cmu.sphinx.decoder.adaptation.ClusteredDensityFileData;
import edu.cmu.sphinx.decoder.adaptation.Transform;
import edu.cmu.sphinx.linguist.acoustic.UnitManager;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.Sphinx3Loader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An adaptation moves each Gaussian mean of the model by the transform of its own feature stream. The
 * model sphinx4-data ships has three streams (cepstra, deltas, double deltas); Sphinx-4's own
 * {@code Sphinx3Loader.update} runs every mean through all three transforms, so a bias meant for the
 * cepstra lands on the deltas too — the bug that made enrolled teachers heard worse.
 */
class MllrTest {

    @Test
    void eachMeanMovesByItsOwnStreamsTransformOnly(@TempDir Path dir) throws Exception {
        Sphinx3Loader loader = new Sphinx3Loader("resource:/edu/cmu/sphinx/models/en-us/en-us", new UnitManager(), 0f,
                1e-7f, 1e-4f, 4, true);
        loader.load();
        int streams = loader.getNumStreams();
        int gaussians = loader.getNumGaussiansPerState();
        assertThat(streams).isEqualTo(3);
        List<float[]> before = snapshot(loader);
        // identity everywhere, and a bias of 2 on every cepstrum (stream 0) only
        Path file = dir.resolve("bias.mllr");
        StringBuilder b = new StringBuilder("1\n3\n");
        for (int s = 0; s < 3; s++) {
            b.append("13\n");
            for (int k = 0; k < 13; k++) {
                for (int p = 0; p < 13; p++) {
                    b.append(k == p ? "1 " : "0 ");
                }
                b.append('\n');
            }
            b.append((s == 0 ? "2 " : "0 ").repeat(13)).append('\n').append("1 ".repeat(13)).append('\n');
        }
        Files.writeString(file, b);

        // Sphinx-4's own update: the deltas move as well
        Transform sphinx = new Transform(loader, 1);
        sphinx.load(file.toString());
        loader.update(sphinx, new ClusteredDensityFileData(loader, 1));
        assertThat(loader.getMeansPool().get(gaussians)[0] - before.get(gaussians)[0])
                .as("a delta mean after Sphinx-4's update").isNotEqualTo(0f);
        restore(loader, before);

        Mllr.read(file).apply(loader);
        for (int index = 0; index < loader.getMeansPool().size(); index++) {
            int stream = (index / gaussians) % streams;
            float[] mean = loader.getMeansPool().get(index);
            for (int k = 0; k < mean.length; k++) {
                assertThat(mean[k] - before.get(index)[k]).as("mean %d (stream %d) dimension %d", index, stream, k)
                        .isCloseTo(stream == 0 ? 2f : 0f, org.assertj.core.data.Offset.offset(1e-4f));
            }
        }
        // written and read back, a transform is the same
        Path again = dir.resolve("again.mllr");
        Mllr.read(file).write(again);
        assertThat(Mllr.read(again).bias(0)).containsExactly(Mllr.read(file).bias(0));
        assertThat(Mllr.read(again).distanceFromIdentity()).isZero();
    }

    private static List<float[]> snapshot(Sphinx3Loader loader) {
        List<float[]> out = new ArrayList<>();
        for (int i = 0; i < loader.getMeansPool().size(); i++) {
            out.add(loader.getMeansPool().get(i).clone());
        }
        return out;
    }

    private static void restore(Sphinx3Loader loader, List<float[]> means) {
        for (int i = 0; i < means.size(); i++) {
            System.arraycopy(means.get(i), 0, loader.getMeansPool().get(i), 0, means.get(i).length);
        }
    }
}
