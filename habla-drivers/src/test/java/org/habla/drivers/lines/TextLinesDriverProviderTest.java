package org.habla.drivers.lines;

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

class TextLinesDriverProviderTest {

    @SuppressWarnings("unchecked")
    private static Driver create(String address, String paramsJson) throws Exception {
        DriverProvider<TextLinesParams> provider = (DriverProvider<TextLinesParams>) PluginRegistry.discover()
                .driver("text-lines").orElseThrow();
        return provider.create(InterfaceAddress.parse(address), ParamsJson.of(provider.paramsType(), paramsJson));
    }

    @Test
    void theTextLinesTypeIsFoundByNameThroughDiscovery() {
        assertThat(PluginRegistry.discover().driver("text-lines")).get().isInstanceOf(TextLinesDriverProvider.class);
    }

    @Test
    void itReadsLinesAndSendsLinesOnPort8111ByDefault() throws Exception {
        Driver d = create("127.0.0.1", "{}");
        assertThat(d.channels()).extracting(ChannelDescriptor::name, ChannelDescriptor::kind, ChannelDescriptor::direction)
                .containsExactly(
                        org.assertj.core.groups.Tuple.tuple("lines", PayloadKind.TEXT, ChannelDescriptor.Direction.READING),
                        org.assertj.core.groups.Tuple.tuple("send", PayloadKind.TEXT, ChannelDescriptor.Direction.COMMAND));
        assertThat(d.connections()).singleElement().satisfies(c -> {
            assertThat(c.port()).isEqualTo(8111);
            assertThat(c.commandChannels()).containsExactly("send");
        });
        assertThat(create("localhost:7777", "{}").connections().get(0).port()).isEqualTo(7777);
    }

    @Test
    void badParamsAreRefusedNamingTheParameter() {
        assertThatThrownBy(() -> create("127.0.0.1", "{\"maxLineBytes\": 0}")).rootCause()
                .hasMessageContaining("maxLineBytes");
        assertThatThrownBy(() -> create("127.0.0.1", "{\"charset\": \"latin1\"}")).hasMessageContaining("unknown parameter");
    }
}
