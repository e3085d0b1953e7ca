package org.habla.methods.audio;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

class AudioMethodsDiscoveryTest {

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Method create(MethodProvider provider, String paramsJson) throws Exception {
        Record params = (Record) ParamsJson.of(provider.paramsType(), paramsJson);
        return provider.create(Layer.PROCESSING, params);
    }

    @Test
    void theAudioTypesAreFoundByNameWithTheirPortsAndParams() throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        Map<String, String> params = Map.of(
                "audio-processing", "{\"frameMs\": 20, \"bands\": 8}",
                "note-recognition", "{\"notes\": [\"C5\", \"E5\", \"G5\", \"C6\"], \"minDurationMs\": 200}",
                "speech-recognition", "{\"maxPending\": 2}");
        Map<String, String> outputs = Map.of(
                "audio-processing", "[features, segments]",
                "note-recognition", "[note]",
                "speech-recognition", "[words, result]");
        for (String type : params.keySet()) {
            MethodProvider<?> provider = registry.method(type).orElseThrow(() -> new AssertionError(type + " not found"));
            assertThat(provider.layers()).containsExactly(Layer.PROCESSING);
            Method m = create(provider, params.get(type));
            assertThat(m.outputs().stream().map(Output::name).toList()).hasToString(outputs.get(type));
            assertThat(m.inputs().stream().map(Input::name).toList()).contains("audio");
        }
        assertThat(registry.method("microphone")).isPresent();
    }
}
