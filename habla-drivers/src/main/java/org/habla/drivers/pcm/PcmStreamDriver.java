package org.habla.drivers.pcm;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.Liveness;
import org.habla.sample.PayloadKind;

/** A microphone (or any PCM source) that streams raw samples over one TCP connection. */
public final class PcmStreamDriver implements Driver {

    /** The port the simulated Pioneer's microphone streams on. */
    public static final int DEFAULT_PORT = 8110;
    /** The reading channel. */
    public static final String AUDIO = "audio";

    /** A PCM source streams without pause (a chunk every chunkMs): three seconds without a byte means it is gone. */
    static final Liveness STREAM = Liveness.periodic(Duration.ofSeconds(3));

    private final int port;
    private final PcmStreamParams params;
    private final List<ChannelDescriptor> channels;

    public PcmStreamDriver(InterfaceAddress address, PcmStreamParams params) {
        this.port = address.portOr(DEFAULT_PORT);
        this.params = params;
        this.channels = List.of(ChannelDescriptor.reading(AUDIO, PayloadKind.AUDIO, "").withMetadata(
                JsonNodeFactory.instance.objectNode()
                        .put("rateHz", params.rateHz())
                        .put("channels", params.channels())
                        .put("bits", params.bits())
                        .put("chunkMs", params.chunkMs())));
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return channels;
    }

    @Override
    public List<Connection> connections() {
        return List.of(new Connection("pcm", port, Set.of(), STREAM, () -> new PcmStreamSession(params)));
    }
}
