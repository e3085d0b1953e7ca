package org.habla.recording;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.habla.driver.ChannelDescriptor;

/**
 * The first record of a recording: the config the daemon ran, where its relative file params were
 * taken from, and every interface's channels as the drivers described them, with their metadata (so a
 * replay needs no robot: the channels come from here, not from a connection).
 *
 * @param startMicros the engine clock when the recording began
 * @param timeScale   the engine clock's speed against the wall clock (1 for a real robot)
 * @param config      the config, as JSON
 * @param configDir   the absolute folder relative file params were read from
 * @param interfaces  each interface id with its channels, in config order
 */
public record RecordingHeader(long startMicros, double timeScale, ObjectNode config, String configDir,
        Map<String, List<ChannelDescriptor>> interfaces) {

    public RecordingHeader {
        Objects.requireNonNull(config, "config");
        Objects.requireNonNull(configDir, "configDir");
        config = config.deepCopy();
        Map<String, List<ChannelDescriptor>> copy = new LinkedHashMap<>();
        interfaces.forEach((id, channels) -> copy.put(id, List.copyOf(channels)));
        interfaces = Collections.unmodifiableMap(copy);
    }

    @Override
    public ObjectNode config() {
        return config.deepCopy();
    }
}
