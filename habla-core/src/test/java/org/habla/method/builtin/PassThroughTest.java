package org.habla.method.builtin;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Delivery;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.MethodHarness;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.NumberValue;
import org.habla.sample.PayloadKind;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class PassThroughTest {

    @Test
    void everySampleIsHandedOnUnchangedWithItsSourceTime() {
        for (Layer layer : Layer.values()) {
            Method m = PassThrough.create(layer, RelayParams.defaults());
            assertThat(m.layer()).isEqualTo(layer);
            MethodHarness h = MethodHarness.started("relay", m);
            h.push("in", VectorValue.of(1, 2, 3), 42L).push("in", new TextValue("hello"), 43L);
            assertThat(h.values("out")).containsExactly(VectorValue.of(1, 2, 3), new TextValue("hello"));
            assertThat(h.samples("out")).extracting(s -> s.sourceMicros()).containsExactly(42L, 43L);
        }
    }

    @Test
    void aKindedRelayDeclaresThatKindAndItsDelivery() {
        Method m = PassThrough.create(Layer.PROCESSING, new RelayParams("number", "queue", 8));
        assertThat(m.input("in").orElseThrow().kind()).isEqualTo(PayloadKind.NUMBER);
        assertThat(m.input("in").orElseThrow().delivery()).isEqualTo(Delivery.queue(8));
        assertThat(m.output("out").orElseThrow().kind()).isEqualTo(PayloadKind.NUMBER);
        MethodHarness h = MethodHarness.started("n", m).push("in", new NumberValue(0.5));
        assertThat(h.last("out")).isEqualTo(new NumberValue(0.5));
    }

    @Test
    void badParamsAreRejectedNamingTheParameter() {
        assertThatThrownBy(() -> ParamsJson.of(RelayParams.class, "{\"kind\": \"sound\"}"))
                .hasMessageContaining("$.params.kind");
        assertThatThrownBy(() -> ParamsJson.of(RelayParams.class, "{\"delivery\": \"stack\"}"))
                .hasMessageContaining("$.params.delivery");
        assertThatThrownBy(() -> ParamsJson.of(RelayParams.class, "{\"capacity\": 0}"))
                .hasMessageContaining("$.params.capacity: must be within [1, 65536], was 0");
    }

    @Test
    void paramsBindStrictlyFromJson() {
        RelayParams p = ParamsJson.of(RelayParams.class, "{\"kind\":\"text\",\"delivery\":\"queue\"}");
        assertThat(p).isEqualTo(new RelayParams("text", "queue", 64));
        assertThatThrownBy(() -> ParamsJson.of(RelayParams.class, "{\"kindd\":\"text\"}"))
                .hasMessageContaining("$.params.kindd: unknown parameter 'kindd'");
    }

    @Test
    void theChannelMethodHandsReadingsOnFromItsChannel() {
        ChannelReader m = new ChannelReader(ParamsJson.of(RelayParams.class, "{\"kind\": \"vector\"}"));
        MethodHarness h = MethodHarness.of("sonarRaw", m)
                .wireChannel("in", ChannelDescriptor.reading("sonar", PayloadKind.VECTOR, "m")).start();
        h.push("in", VectorValue.of(0.5, 4.0));
        assertThat(h.last("out")).isEqualTo(VectorValue.of(0.5, 4.0));
        assertThat(m.layer()).isEqualTo(Layer.SENSORS_ACTUATORS);
    }

    @Test
    void bothBuiltInTypesAreFoundByNameAndRefuseForeignLayers() {
        PluginRegistry registry = PluginRegistry.discover();
        MethodProvider<?> pass = registry.method("pass-through").orElseThrow();
        MethodProvider<?> channel = registry.method("channel").orElseThrow();
        assertThat(pass.layers()).containsExactlyInAnyOrder(Layer.values());
        assertThat(channel.layers()).containsExactly(Layer.SENSORS_ACTUATORS);
        assertThat(create(pass, Layer.VIRTUAL).layer()).isEqualTo(Layer.VIRTUAL);
        assertThat(create(channel, Layer.SENSORS_ACTUATORS)).isInstanceOf(ChannelReader.class);
        assertThatThrownBy(() -> create(channel, Layer.VIRTUAL)).hasMessageContaining("cannot be placed in the virtual");
    }

    @SuppressWarnings("unchecked")
    private static Method create(MethodProvider<?> provider, Layer layer) {
        return ((MethodProvider<RelayParams>) provider).create(layer, RelayParams.defaults());
    }
}
