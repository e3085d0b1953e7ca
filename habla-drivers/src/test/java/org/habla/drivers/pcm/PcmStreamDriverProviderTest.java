package org.habla.drivers.pcm;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.PayloadKind;
import org.junit.jupiter.api.Test;

class PcmStreamDriverProviderTest {

    @SuppressWarnings("unchecked")
    private static Driver create(String address, String paramsJson) throws Exception {
        DriverProvider<PcmStreamParams> provider = (DriverProvider<PcmStreamParams>) PluginRegistry.discover()
                .driver("pcm-stream").orElseThrow();
        return provider.create(InterfaceAddress.parse(address), ParamsJson.of(provider.paramsType(), paramsJson));
    }

    @Test
    void thePcmStreamTypeIsFoundByNameThroughDiscovery() {
        assertThat(PluginRegistry.discover().driver("pcm-stream")).get().isInstanceOf(PcmStreamDriverProvider.class);
    }

    @Test
    void itOffersOneAudioReadingOnPort8110ByDefault() throws Exception {
        Driver d = create("127.0.0.1", "{}");
        assertThat(d.channels()).singleElement().satisfies(c -> {
            assertThat(c.name()).isEqualTo("audio");
            assertThat(c.kind()).isEqualTo(PayloadKind.AUDIO);
            assertThat(c.direction()).isEqualTo(ChannelDescriptor.Direction.READING);
            assertThat(c.metadata().path("rateHz").asInt()).isEqualTo(16_000);
        });
        assertThat(d.connections().get(0).port()).isEqualTo(8110);
        assertThat(d.connections().get(0).commandChannels()).isEmpty();
        assertThat(create("127.0.0.1:9000", "{\"rateHz\": 8000}").connections().get(0).port()).isEqualTo(9000);
    }

    @Test
    void theChunkIsAWholeNumberOfFrames() {
        PcmStreamParams p = new PcmStreamParams(22_050, 2, 16, 10);
        assertThat(p.framesPerChunk()).isEqualTo(220);
        assertThat(p.bytesPerChunk()).isEqualTo(880);
    }

    @Test
    void badParamsAreRefusedNamingTheParameter() {
        assertThatThrownBy(() -> create("127.0.0.1", "{\"bits\": 24}")).hasMessageContaining("bits");
        assertThatThrownBy(() -> create("127.0.0.1", "{\"chunkMs\": 0}")).hasMessageContaining("chunkMs");
        assertThatThrownBy(() -> create("127.0.0.1", "{\"rateHz\": -1}")).hasMessageContaining("rateHz");
        assertThatThrownBy(() -> create("127.0.0.1", "{\"rate\": 16000}")).hasMessageContaining("unknown parameter");
    }
}
