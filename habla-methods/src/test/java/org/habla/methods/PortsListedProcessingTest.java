package org.habla.methods;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.Delivery;
import org.habla.method.Layer;
import org.habla.method.Ports;
import org.habla.methods.audio.AudioProcessing;
import org.habla.methods.audio.AudioProcessingParams;
import org.habla.methods.emotion.EmotionRecognition;
import org.habla.methods.emotion.EmotionRecognitionParams;
import org.habla.methods.gaze.HeadControl;
import org.habla.methods.gaze.HeadControlParams;
import org.habla.methods.locomotion.GaitComposition;
import org.habla.methods.locomotion.GaitCompositionParams;
import org.habla.methods.motion.MotionComposition;
import org.habla.methods.motion.MotionCompositionParams;
import org.habla.methods.motion.MovementSafety;
import org.habla.methods.motion.MovementSafetyParams;
import org.habla.methods.notes.NoteRecognition;
import org.habla.methods.notes.NoteRecognitionParams;
import org.habla.methods.position.CoordinateTranslation;
import org.habla.methods.position.CoordinateTranslationParams;
import org.habla.methods.speech.SpeechRecognition;
import org.habla.methods.speech.SpeechRecognitionParams;
import org.habla.methods.vision.ImageSegmentation;
import org.habla.methods.vision.ImageSegmentationParams;
import org.habla.plugin.MethodProvider;
import org.junit.jupiter.api.Test;

/**
 * The processing, gaze, motion, audio, speech and vision types list their ports without making a method, and
 * the methods they make bind exactly those.
 */
class PortsListedProcessingTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    /** The ports the provider lists for {@code params}, once a method made with them passed the engine's check. */
    private static <P extends Record> Ports listed(MethodProvider<P> provider, Layer layer, P params) {
        assertThatCode(() -> MethodProvider.make(provider, layer, params)).as(provider.name())
                .doesNotThrowAnyException();
        return provider.ports(layer, params);
    }

    private static List<String> names(List<? extends Ports.Port> ports) {
        return ports.stream().map(Ports.Port::name).toList();
    }

    private static void assertPorts(Ports ports, List<String> inputs, List<String> outputs) {
        assertThat(names(ports.inputs())).containsExactlyInAnyOrderElementsOf(inputs);
        assertThat(names(ports.outputs())).containsExactlyInAnyOrderElementsOf(outputs);
    }

    private static <P extends Record> P params(String json, Class<P> type) {
        return ParamsJson.of(type, json);
    }

    @Test
    void typesWithFixedPortsListWhatTheirMethodsBind() {
        assertPorts(listed(new EmotionRecognition.Provider(), Layer.VIRTUAL, EmotionRecognitionParams.defaults()),
                List.of("words", "features", "touch", "reward"), List.of("emotion"));
        assertPorts(listed(new HeadControl.Provider(), Layer.PROCESSING, HeadControlParams.defaults()),
                List.of("blobs", "camera", "head"), List.of("head"));
        assertPorts(listed(new GaitComposition.Provider(), Layer.PROCESSING, GaitCompositionParams.defaults()),
                List.of("motion"), List.of("walk"));
        assertPorts(listed(new MotionComposition.Provider(), Layer.PROCESSING, MotionCompositionParams.defaults()),
                List.of("motion", "limits"), List.of("motion"));
        assertPorts(listed(new MovementSafety.Provider(), Layer.PROCESSING, MovementSafetyParams.defaults()),
                List.of("motion", "nearest", "limits"), List.of("motion", "veto"));
        assertPorts(listed(new CoordinateTranslation.Provider(), Layer.PROCESSING,
                CoordinateTranslationParams.defaults()),
                List.of("nearest", "blobs", "head", "camera", "odometry"), List.of("position"));
        assertPorts(listed(new ImageSegmentation.Provider(), Layer.PROCESSING, ImageSegmentationParams.defaults()),
                List.of("image"), List.of("blobs", "largest"));
    }

    @Test
    void audioTypesListTheirInputQueuesAtTheDefaultLength() {
        assertAudioPorts(AudioProcessingParams.defaults(), NoteRecognitionParams.defaults(),
                SpeechRecognitionParams.defaults(), 256);
    }

    @Test
    void audioTypesListTheirInputQueuesAtTheLengthTheParamsAskFor() throws Exception {
        String queue = "{\"queue\": 8}";
        assertAudioPorts(params(queue, AudioProcessingParams.class), params(queue, NoteRecognitionParams.class),
                params(queue, SpeechRecognitionParams.class), 8);
    }

    private static void assertAudioPorts(AudioProcessingParams audio, NoteRecognitionParams notes,
            SpeechRecognitionParams speech, int queue) {
        Ports a = listed(new AudioProcessing.Provider(), Layer.PROCESSING, audio);
        assertPorts(a, List.of("audio"), List.of("features", "segments"));
        assertThat(a.input("audio").orElseThrow().delivery()).isEqualTo(Delivery.queue(queue));

        Ports n = listed(new NoteRecognition.Provider(), Layer.PROCESSING, notes);
        assertPorts(n, List.of("audio"), List.of("note"));
        assertThat(n.input("audio").orElseThrow().delivery()).isEqualTo(Delivery.queue(queue));

        Ports s = listed(new SpeechRecognition.Provider(), Layer.PROCESSING, speech);
        assertPorts(s, List.of("segments", "audio"), List.of("words", "result"));
        assertThat(s.input("segments").orElseThrow().delivery()).isEqualTo(Delivery.queue(queue));
        assertThat(s.input("audio").orElseThrow().delivery()).isEqualTo(Delivery.queue(queue));
    }
}
