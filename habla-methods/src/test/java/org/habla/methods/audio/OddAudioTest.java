package org.habla.methods.audio;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.methods.notes.NoteRecognitionParams;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.junit.jupiter.api.Test;

/** Audio no microphone should send still leaves the audio methods running and working. */
class OddAudioTest {

    private static List<AudioChunk> oddChunks() {
        Random r = new Random(11);
        byte[] garbage = new byte[3000];
        r.nextBytes(garbage);
        byte[] fullScale = new byte[2000];
        for (int i = 0; i < fullScale.length; i += 2) {
            fullScale[i] = (byte) 0xff;
            fullScale[i + 1] = (byte) ((i / 2) % 2 == 0 ? 0x7f : 0x80);
        }
        return List.of(
                AudioChunk.of(AudioFormat.MONO_16K, new byte[0]),
                AudioChunk.of(new AudioFormat(16_000, 1, 8), garbage),
                AudioChunk.of(new AudioFormat(192_000, 8, 16), new byte[16 * 7]),
                AudioChunk.of(new AudioFormat(1, 1, 16), new byte[20]),
                AudioChunk.of(new AudioFormat(11_025, 2, 16), garbage),
                AudioChunk.of(AudioFormat.MONO_16K, fullScale));
    }

    @Test
    void emptyTinyGarbageAndStrangeFormatsNeverFailAnAudioMethod() throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        for (String type : List.of("audio-processing", "note-recognition")) {
            var provider = registry.method(type).orElseThrow();
            Record params = type.equals("audio-processing") ? AudioProcessingParams.defaults()
                    : NoteRecognitionParams.defaults();
            @SuppressWarnings({"unchecked", "rawtypes"})
            MethodHarness h = MethodHarness.started(type,
                    ((org.habla.plugin.MethodProvider) provider).create(org.habla.method.Layer.PROCESSING, params));
            for (int round = 0; round < 3; round++) {
                for (AudioChunk c : oddChunks()) {
                    h.push("audio", c);
                }
            }
            assertThat(h.state()).as(type).isEqualTo(MethodState.RUNNING);
            Signals.stream(h, "audio", Signals.tone(523.25, 0.3, 0.5, 16_000), AudioFormat.MONO_16K, 20, 0);
            assertThat(h.state()).as(type).isEqualTo(MethodState.RUNNING);
        }
    }
}
